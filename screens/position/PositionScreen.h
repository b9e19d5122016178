#pragma once

#include <QVector>

#include "cnc_core/cell/StationStatus.h"
#include "hmi/Screen.h"

class QGridLayout;
class QLabel;

namespace mtc::screens {

/// The operator's base screen ("position"): per axis the actual position
/// in workpiece and machine coordinates and the distance to go, feeds,
/// spindles, overrides, the active G functions, tool and edge, the zero
/// offset, the running block with its neighbours and call level, and the
/// program status. It renders core::describeStation() of its station at
/// every change the panel's timer announces; it owns no behaviour.
///
/// Children for tests: "programState", "blockContext", "blockList",
/// "feedValues", "feedOverride", "rapidOverride", "spindleValues",
/// "gFunctions", "toolValues", "zeroOffset"; per shown axis n (0-based)
/// "axisName-n", "axisWork-n", "axisMachine-n", "axisToGo-n".
class PositionScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    explicit PositionScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "position"; }
    QString title() const override { return "Base screen (position)"; }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

    /// What the screen shows now (the last refresh).
    const mtc::core::StationStatus& status() const { return status_; }

  protected:
    void showEvent(QShowEvent* event) override;

  private:
    void refresh();
    void showAxes();
    void showFeedsAndSpindles();
    void showModal();
    void showBlocks();
    /// Adds the row of labels for axis `row` (name, workpiece, machine, to go).
    void addAxisRow(int row);

    mtc::core::StationStatus status_;
    QGridLayout* axisGrid_;
    QVector<QVector<QLabel*>> axisRows_;
    QLabel* state_;
    QLabel* blockContext_;
    QLabel* blocks_;
    QLabel* feeds_;
    QLabel* feedOverride_;
    QLabel* rapidOverride_;
    QLabel* spindles_;
    QLabel* gFunctions_;
    QLabel* tool_;
    QLabel* zeroOffset_;
};

}  // namespace mtc::screens
