#pragma once

#include <memory>

#include "hmi/Screen.h"
#include "screens/runtime/RuntimeListing.h"

class QLabel;

namespace mtc::hmi {
class ProgramWorkspace;
}

namespace mtc::screens {

class NcCodeEdit;
class VelocityPlot;

/// Runtime program view (seed 001, ch. 1 and 12): the source program beside
/// the compiled (runtime) program; blocks the compiler inserted are marked
/// with an arrow; moving through the compiled program marks the source line
/// each block stems from; below, the look-ahead velocity profile of the
/// compile (seed 001 ch. 6, Fig. 6-1). Read-only.
class RuntimeScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    RuntimeScreen(const mtc::hmi::ScreenContext& context,
                  std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace);
    QString screenName() const override { return "runtime"; }
    QString title() const override { return "Runtime program"; }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

    /// The listing shown on the right (empty when the program is not compiled).
    const RuntimeListing& listing() const { return listing_; }
    VelocityPlot* plot() const { return plot_; }

  private:
    void showProgram();
    void followCompiledCursor();
    void showSegment(int index);

    std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace_;
    NcCodeEdit* source_;
    NcCodeEdit* compiled_;
    QLabel* heading_;
    QLabel* note_;
    VelocityPlot* plot_;
    int segment_ = 0;
    RuntimeListing listing_;
    int program_ = 0;
};

}  // namespace mtc::screens
