#include "cnc_core/restart/ReposPreview.h"

#include <memory>

#include "cnc_core/interp/ProgramFlow.h"

namespace mtc::core {

namespace {

/// Reads through to the station's machine data; writes are checked and
/// answered but never reach it (the preview changes nothing).
class ReadOnlyMachineData : public MachineDataProvider {
  public:
    explicit ReadOnlyMachineData(const MachineDataProvider& data) : data_(data) {}
    MachineDataStatus read(const MachineDataAddress& address, double& value) const override {
        return data_.read(address, value);
    }
    MachineDataStatus check(const MachineDataAddress& address, double value,
                            MachineDataWriter writer) const override {
        return data_.check(address, value, writer);
    }
    MachineDataStatus write(const MachineDataAddress& address, double value,
                            MachineDataWriter writer) override {
        return data_.check(address, value, writer);
    }

  private:
    const MachineDataProvider& data_;
};

/// Records the end of every move; everything else is dropped.
class CornerSink : public MachineSink {
  public:
    explicit CornerSink(ReposPreview& preview) : preview_(preview) {}
    void motion(const Motion& m) override {
        preview_.corners.push_back(m.end);
        preview_.blocks.push_back(m.where);
    }
    void auxiliary(const AuxOutput&) override {}
    void dwell(const SourceLocation&, double) override {}
    void command(const MachineCommand&) override {}

  private:
    ReposPreview& preview_;
};

/// Puts the program pointer on .ADJUST, called from the target block (as
/// RestartSequence::beginAdjust does). False when there is no ADJUST.
bool enterAdjust(const ProgramStore& programs, const ProcessConfig& config,
                 InterpreterState& state) {
    ProgramPtr program;
    std::uint32_t block = 0;
    if (!ProgramFlow(programs, config.index, nullptr)
             .findLabel(state.selected, "ADJUST", program, block))
        return false;
    state.callStack.push_back({state.program, state.block, state.block});
    state.program = program;
    state.block = block;
    return true;
}

}  // namespace

ReposPreview previewRepositioning(const ProcessConfig& config, const ProgramStore& programs,
                                  const MachineDataProvider& data, const ReposPreviewStart& start,
                                  std::uint64_t budget) {
    ReposPreview preview;
    preview.corners.push_back(start.state.modal.machine);
    InterpreterState state = start.state;
    if (start.beforeAdjust && !enterAdjust(programs, config, state)) {
        preview.diagnostics.warning("RESTART_ADJUST_MISSING", {},
                                    "no ADJUST subroutine: no repositioning path");
        return preview;
    }
    CornerSink sink(preview);
    InterpreterServices services;
    services.machineData = std::make_shared<ReadOnlyMachineData>(data);
    Interpreter interpreter(config, programs, sink, services);
    interpreter.restoreState(state);
    interpreter.options() = start.options;
    interpreter.setStopTarget(start.target);
    for (std::uint64_t used = 0; used < budget;) {
        RunResult result = interpreter.step();
        used += result.blocksInterpreted == 0 ? 1 : result.blocksInterpreted;
        preview.diagnostics.append(result.diagnostics);
        if (result.status == RunStatus::TargetReached) {
            preview.reachesTarget =
                callStackMatches(interpreter.state().callStack, start.targetChain);
            if (preview.reachesTarget) return preview;
            interpreter.setStopTarget(std::nullopt);  // the target inside ADJUST / REPOS: run it
            result = interpreter.step();
            interpreter.setStopTarget(start.target);
            preview.diagnostics.append(result.diagnostics);
        }
        if (result.status != RunStatus::Running && result.status != RunStatus::TargetReached)
            return preview;
    }
    return preview;
}

}  // namespace mtc::core
