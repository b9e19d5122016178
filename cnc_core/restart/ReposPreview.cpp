#include "cnc_core/restart/ReposPreview.h"

#include <memory>
#include <optional>
#include <utility>

#include "cnc_core/interp/ProgramFlow.h"
#include "cnc_core/restart/RestartSequence.h"

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

/// Records every move with its tool and phase; everything else is dropped.
class CornerSink : public MachineSink {
  public:
    explicit CornerSink(ReposPreview& preview) : preview_(preview) {}
    /// Where the tool in working position comes from.
    void setInterpreter(const Interpreter* interpreter) { interpreter_ = interpreter; }
    /// From now on the moves belong to REPOS.
    void enterRepos() { repos_ = true; }
    void motion(const Motion& m) override {
        preview_.corners.push_back(m.end);
        preview_.blocks.push_back(m.where);
        ToolData tool;
        if (interpreter_ != nullptr)
            tool = activeToolData(interpreter_->tools(), interpreter_->state().modal);
        preview_.moves.push_back({m, tool, repos_});
    }
    void auxiliary(const AuxOutput&) override {}
    void dwell(const SourceLocation&, double) override {}
    void command(const MachineCommand&) override {}

  private:
    ReposPreview& preview_;
    const Interpreter* interpreter_ = nullptr;
    bool repos_ = false;
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

/// The block of the .REPOS label after .ADJUST (as RestartSequence::beginAdjust finds it).
std::optional<std::pair<int, std::uint32_t>> reposLabel(const ProgramStore& programs,
                                                        const ProcessConfig& config,
                                                        const InterpreterState& state) {
    ProgramPtr program;
    std::uint32_t block = 0;
    if (!ProgramFlow(programs, config.index, nullptr)
             .findLabel(state.selected, "ADJUST", program, block))
        return std::nullopt;
    const long repos = program->findLabel("REPOS");
    if (repos <= static_cast<long>(block)) return std::nullopt;
    return std::make_pair(program->number, static_cast<std::uint32_t>(repos));
}

bool standsAt(const InterpreterState& state, const std::pair<int, std::uint32_t>& block) {
    return state.program && state.program->number == block.first && state.block == block.second;
}

InterpreterServices previewServices(const MachineDataProvider& data,
                                    const ReposPreviewStart& start) {
    InterpreterServices services;
    services.machineData = std::make_shared<ReadOnlyMachineData>(data);
    // Not owned: the preview runs and ends within previewRepositioning.
    if (start.tools != nullptr)
        services.tools = std::shared_ptr<const ToolList>(std::shared_ptr<void>(), start.tools);
    if (start.zeroOffsets != nullptr)
        services.zeroOffsets =
            std::shared_ptr<const ZeroOffsetTable>(std::shared_ptr<void>(), start.zeroOffsets);
    return services;
}

}  // namespace

std::optional<ReposPreviewStart> reposPreviewStart(const RestartSequence& sequence,
                                                   const Interpreter& live) {
    const RestartPhase phase = sequence.phase();
    const bool ahead = phase == RestartPhase::TargetReached || phase == RestartPhase::Adjusting ||
                       phase == RestartPhase::ManualMode || phase == RestartPhase::AutomaticAgain ||
                       phase == RestartPhase::Repositioning;
    const RestartRoute& route = sequence.computing().route();
    if (!ahead || !sequence.reentry().valid || !route.targetProgram) return std::nullopt;
    ReposPreviewStart start;
    start.state = live.state();
    start.options = live.options();
    start.target = {route.targetProgram->number, sequence.computing().selection().target.block, 1};
    start.targetChain = route.targetChain;
    start.beforeAdjust = phase == RestartPhase::TargetReached;
    start.inRepos = phase == RestartPhase::Repositioning;
    start.tools = &live.tools();
    start.zeroOffsets = &live.zeroOffsets();
    return start;
}

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
    Interpreter interpreter(config, programs, sink, previewServices(data, start));
    sink.setInterpreter(&interpreter);
    if (start.inRepos) sink.enterRepos();
    const auto repos = reposLabel(programs, config, state);
    interpreter.restoreState(state);
    interpreter.options() = start.options;
    interpreter.setStopTarget(start.target);
    for (std::uint64_t used = 0; used < budget;) {
        if (repos && standsAt(interpreter.state(), *repos)) sink.enterRepos();
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
