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
/// "gFunctions", "toolValues", "zeroOffset", "jogLine"; per shown axis n
/// (0-based) "axisName-n", "axisWork-n", "axisMachine-n", "axisToGo-n".
///
/// Manual mode (issue 17 §2): ↑/↓ choose the axis, + / − jog it by the step
/// (F6: continuous while held, 0.001 … 10), F7 switches rapid on and off,
/// the mouse wheel over the screen is the handwheel (one detent = one step;
/// 0.01 in continuous). The keys go to the station (Station::jogBy /
/// jogStart / jogRelease), which moves the axes and refuses with a reason.
class PositionScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    explicit PositionScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "position"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Base screen (position)");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

    /// What the screen shows now (the last refresh).
    const mtc::core::StationStatus& status() const { return status_; }

  protected:
    void showEvent(QShowEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

  private:
    void refresh();
    void showAxes();
    void showFeedsAndSpindles();
    void showModal();
    void showBlocks();
    /// Adds the row of labels for axis `row` (name, workpiece, machine, to go).
    void addAxisRow(int row);
    void showJogLine();
    /// A manual spindle key (3, 4, 5, PgUp, PgDn); false when `key` is none.
    bool spindleKey(int key);
    bool manualMode() const;
    /// Machine axis index of the chosen jog axis (-1: none shown).
    int jogAxis() const;
    /// The step of one press or detent (mm, degrees); 0 = continuous.
    double jogStep() const;

    int jogRow_ = 0;      ///< row of the axis table jogged
    int stepIndex_ = 3;   ///< -1 continuous, else kJogIncrements (1 mm)
    bool rapid_ = false;  ///< jog at rapid traverse
    bool jogKeyHeld_ = false;
    QLabel* jogLine_;
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
