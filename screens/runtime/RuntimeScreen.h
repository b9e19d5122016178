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
/// the compiled (runtime) program; the compiler's intermediate blocks carry
/// their enhanced numbers, the blocks the control inserts while it runs (tool
/// compensation) are marked with an arrow; moving through the compiled program marks the source
/// line each block stems from; below, the look-ahead velocity profile of the compile (seed 001 ch.
/// 6, Fig. 6-1). Read-only.
class RuntimeScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    RuntimeScreen(const mtc::hmi::ScreenContext& context,
                  std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace);
    QString screenName() const override { return "runtime"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Runtime program");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

    /// The listing shown on the right (empty when the program is not compiled).
    const RuntimeListing& listing() const { return listing_; }
    VelocityPlot* plot() const { return plot_; }

  private:
    /// Blocks of the first blocks of a run the check run of the runtime view looks at.
    static constexpr std::uint64_t kInsertionBudget = 200'000;

    void showProgram();
    /// The blocks tool compensation inserts into the shown program (empty
    /// when it uses no G41/G42).
    std::vector<mtc::core::InsertedBlock> insertedBlocks(
        const mtc::core::ProgramPtr& runtime) const;
    /// The program the station runs for the shown number: the compile
    /// result's object program, the source when it needs no compiling, else
    /// nullptr.
    mtc::core::ProgramPtr runtimeProgram(const mtc::core::ProgramPtr& source,
                                         const mtc::core::CompileResult* result,
                                         mtc::core::CompileStatus status) const;
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
