#include "cnc_core/cell/StationStatus.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/cell/Station.h"
#include "cnc_core/interp/AuxFunctionGroups.h"
#include "cnc_core/interp/ModalGroups.h"
#include "cnc_core/interp/MotionPlanner.h"
#include "cnc_core/machine/AxisNameTable.h"

namespace mtc::core {

namespace {

/// The block's source text on one line, at most `limit` characters.
std::string oneLine(std::string_view text, std::size_t limit = 160) {
    std::string line;
    line.reserve(std::min(text.size(), limit));
    for (char c : text) {
        if (line.size() >= limit) break;
        const bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
        if (space && (line.empty() || line.back() == ' ')) continue;
        line.push_back(space ? ' ' : c);
    }
    while (!line.empty() && line.back() == ' ')
        line.pop_back();
    return line;
}

/// The last M of each group, as of the same block.
const std::array<int, 17>& shownMGroups(const Station& station) {
    const QueuedBlockState* executing = station.executingBlockState();
    return executing ? executing->mGroups : station.interpreter().state().mGroups;
}

/// The program and block the station shows as current, and its call level.
struct ShownBlock {
    ProgramPtr program;
    std::uint32_t index = 0;
    int level = 0;
};

/// Call level of `program` in the interpreter: the innermost level that
/// runs it (the interpreter may be a block ahead of the machine).
int levelOf(const InterpreterState& state, const Program* program) {
    if (state.program.get() == program) return static_cast<int>(state.callStack.size());
    for (std::size_t i = state.callStack.size(); i-- > 0;)
        if (state.callStack[i].program.get() == program) return static_cast<int>(i);
    return 0;
}

/// A program of the current run with number `number` (nullptr = none).
ProgramPtr runProgram(const Station& station, int number) {
    const InterpreterState& state = station.interpreter().state();
    if (state.program && state.program->number == number) return state.program;
    for (std::size_t i = state.callStack.size(); i-- > 0;)
        if (state.callStack[i].program && state.callStack[i].program->number == number)
            return state.callStack[i].program;
    if (station.lastInterpretedProgram() && station.lastInterpretedProgram()->number == number)
        return station.lastInterpretedProgram();
    if (state.selected && state.selected->number == number) return state.selected;
    return nullptr;
}

ShownBlock shownBlock(const Station& station) {
    // As Station::showCurrentBlock: the block the machine executes; while it
    // stands, the one interpreted last.
    ShownBlock shown;
    if (const QueuedBlockState* executing = station.executingBlockState()) {
        shown.program = executing->source;
        shown.index = executing->index;
        shown.level = executing->callLevel;
        return shown;
    }
    const SimulatedMachine& machine = station.machine();
    const SourceLocation at = machine.currentLocation();
    if (!machine.idle() && at.line > 0) {
        shown.program = runProgram(station, at.program);
        if (shown.program) shown.index = blockIndexAtLine(*shown.program, at.line);
    }
    if (!shown.program && station.lastInterpretedProgram()) {
        shown.program = station.lastInterpretedProgram();
        shown.index = station.lastInterpretedBlock();
    }
    if (shown.program) shown.level = levelOf(station.interpreter().state(), shown.program.get());
    return shown;
}

void describeBlocks(const Station& station, int around, StationStatus& status) {
    const ShownBlock shown = shownBlock(station);
    if (!shown.program || shown.program->blocks.size() == 0) return;
    const Program& program = *shown.program;
    const std::uint32_t count = static_cast<std::uint32_t>(program.blocks.size());
    const std::uint32_t current = std::min(shown.index, count - 1);
    const std::uint32_t span = static_cast<std::uint32_t>(std::max(0, around));
    const std::uint32_t first = current > span ? current - span : 0;
    const std::uint32_t last = std::min(count - 1, current + span);
    for (std::uint32_t i = first; i <= last; ++i) {
        const Block& block = program.blocks[i];
        status.blocks.push_back(
            {program.blockId(i), oneLine(program.text(block.sourceText)), i == current});
    }
    status.program = program.number;
    status.callLevel = shown.level;
    const InterpreterState& state = station.interpreter().state();
    const int selected =
        state.selected ? state.selected->number : station.control().selectedProgram();
    status.inLibrary = program.number == 99 && selected != 99;
}

SpindleTurn turnOf(int mFunction, int spindle) {
    if (mFunction < 0) return SpindleTurn::Unknown;
    const int owner = mFunction / 100 == 0 ? 1 : mFunction / 100;
    if (owner != spindle) return SpindleTurn::Unknown;
    switch (mFunction % 100) {
        case 3:
            return SpindleTurn::Clockwise;
        case 4:
            return SpindleTurn::CounterClockwise;
        case 5:
            return SpindleTurn::Stopped;
        case 19:
            return SpindleTurn::Oriented;
        default:
            return SpindleTurn::Unknown;
    }
}

/// The spindle's direction: the last M of the group its M3 belongs to
/// (M3 / M103 for S1, Mj03 for Sj; the interpreter's group rule). Unknown
/// when that group is group 16 and its last M is not one of the spindle's.
SpindleTurn spindleTurn(const Station& station, const AuxFunctionGroups& groups, int spindle) {
    const std::array<int, 17>& mGroups = shownMGroups(station);
    const int candidates[2] = {spindle * 100 + 3, spindle == 1 ? 3 : -1};
    for (int m : candidates) {
        if (m < 0) continue;
        const int number = groups.groupOf(m);
        if (number < 1 || number > 16) continue;
        const SpindleTurn turn = turnOf(mGroups[static_cast<std::size_t>(number)], spindle);
        if (turn != SpindleTurn::Unknown) return turn;
    }
    return SpindleTurn::Unknown;
}

void describeSpindles(const Station& station, StationStatus& status) {
    const ModalState& modal = shownModalState(station);
    const motion::SpindleSet& machineSpindles = station.machine().spindles();
    const ProcessAxes& axes = station.interpreter().axes();
    const AuxFunctionGroups groups(station.config());
    for (int a = 0; a < axes.count(); ++a) {
        const AxisModel& model = axes.axis(a);
        if (!model.spindle || model.spindleIndex < 1 || model.spindleIndex >= kSpindleSlots)
            continue;
        const auto j = static_cast<std::size_t>(model.spindleIndex);
        SpindleStatus spindle;
        spindle.index = model.spindleIndex;
        spindle.name = model.configName;
        // What the machine's spindle was told last (a program's S and M3 once
        // the axes reach them, or the manual spindle keys), the M19 of the
        // program as such.
        using Rotation = motion::SpindleSet::Rotation;
        spindle.programmed = machineSpindles.commandedSpeed(model.spindleIndex);
        const Rotation rotation = machineSpindles.rotation(model.spindleIndex);
        const SpindleTurn programmed = spindleTurn(station, groups, model.spindleIndex);
        spindle.turn = rotation == Rotation::Clockwise          ? SpindleTurn::Clockwise
                       : rotation == Rotation::CounterClockwise ? SpindleTurn::CounterClockwise
                       : programmed == SpindleTurn::Oriented    ? SpindleTurn::Oriented
                                                                : SpindleTurn::Stopped;
        spindle.rotaryAxisMode = modal.rotaryAxisMode[j] != 0;
        // The machine's spindle ramps to its speed (motion::SpindleSet).
        spindle.actual = spindle.rotaryAxisMode
                             ? 0.0
                             : std::abs(machineSpindles.actualSpeed(model.spindleIndex));
        status.spindles.push_back(spindle);
    }
}

void describeAxes(const Station& station, StationStatus& status) {
    const Interpreter& interpreter = station.interpreter();
    const ProcessAxes& axes = interpreter.axes();
    const SimulatedMachine& machine = station.machine();
    // Workpiece coordinates of where the axes ARE: the interpreter's view
    // of the actual machine positions (zero offset, allocation, transformation).
    std::array<double, kMaxAxes> actual{};
    for (int a = 0; a < axes.count() && a < kMaxAxes; ++a)
        actual[static_cast<std::size_t>(a)] = machine.position(a);
    const ModalState& modal = shownModalState(station);
    const std::array<double, kMaxAxes> work = interpreter.programView(actual, modal);
    const MotionPlanner planner(&axes, &interpreter.zeroOffsets());
    for (int a = 0; a < axes.count() && a < kMaxAxes; ++a) {
        const AxisModel& model = axes.axis(a);
        if (model.spindle && !model.rotary) continue;  // a plain spindle turns, it has no position
        AxisStatus axis;
        axis.index = a;
        axis.name = programmedAxisName(axes, modal.transformation, a);
        axis.rotary = model.rotary && !modal.transformation.transforms(a);
        axis.machine = machine.position(a);
        axis.work = work[static_cast<std::size_t>(a)];
        axis.toGo = machine.distanceToGo(a);
        status.axes.push_back(axis);
        status.zeroOffsetValues.push_back(planner.offsetOf(modal, a));
    }
}

void describeTool(const Station& station, StationStatus& status) {
    const ModalState& modal = shownModalState(station);
    status.tool = modal.tool;
    status.edge = modal.edge;
    const ToolEdge* edge = station.interpreter().tools().edge(modal.tool, modal.edge);
    if (modal.tool <= 0 || !edge) return;
    status.edgeKnown = true;
    status.edgeRadius = edge->totalRadius();
    for (int i = 0; i < 3; ++i)
        status.edgeLength[i] = edge->totalLength(i + 1);
    status.edgeOrientation = edge->orientation;
}

}  // namespace

ProgramState programStateOf(const Station& station) {
    const ProcessControl& control = station.control();
    if (station.restart().active())
        return station.restart().phase() == RestartPhase::Active ? ProgramState::WaitingForSps
                                                                 : ProgramState::Restart;
    if (!control.programActive()) {
        const RunStatus ended = station.runStatus();
        if ((ended == RunStatus::Error || ended == RunStatus::BudgetExceeded) &&
            !control.alarm().empty())
            return ProgramState::Error;
        return control.selectedProgram() == 0 ? ProgramState::NoProgram : ProgramState::Ready;
    }
    if (!station.waitingAxis().empty()) return ProgramState::WaitingForAxis;
    if (station.atProgrammedStop()) return ProgramState::ProgrammedStop;
    if (station.atSingleBlockStop()) return ProgramState::SingleBlock;
    if (control.programHeld()) return ProgramState::FeedHold;
    return ProgramState::Running;
}

bool keyLamp(const Station& station, ControlKey key) {
    const ProcessControl& control = station.control();
    const SignalTable& signals = control.signalTable();
    switch (key) {
        case ControlKey::Manual:
            return control.mode() == OperatingMode::Manual;
        case ControlKey::Automatic:
            return control.mode() == OperatingMode::Automatic;
        case ControlKey::Mdi:
            return control.mode() == OperatingMode::Mdi;
        case ControlKey::Start:
            return (control.programActive() && !control.programHeld()) || station.computing();
        case ControlKey::Stop:
            return control.programActive() && control.programHeld();
        case ControlKey::SingleBlock:
            return control.singleBlock();
        case ControlKey::ProgramRestart:
            return station.restart().active() || signals.get("mBPREP") == 1;
        case ControlKey::Repos:
            return signals.get(control.signalPrefix() + "CREPOS") == 1;
        case ControlKey::ControlReset:
            return false;
    }
    return false;
}

const ModalState& shownModalState(const Station& station) {
    const QueuedBlockState* executing = station.executingBlockState();
    return executing ? executing->modal : station.interpreter().state().modal;
}

const char* spindleTurnName(SpindleTurn turn) {
    switch (turn) {
        case SpindleTurn::Clockwise:
            return "CW (M3)";
        case SpindleTurn::CounterClockwise:
            return "CCW (M4)";
        case SpindleTurn::Stopped:
            return "stopped (M5)";
        case SpindleTurn::Oriented:
            return "oriented (M19)";
        case SpindleTurn::Unknown:
            break;
    }
    return "-";
}

const char* programStateName(ProgramState state) {
    switch (state) {
        case ProgramState::NoProgram:
            return "no program selected";
        case ProgramState::Ready:
            return "ready: Start runs the program";
        case ProgramState::Running:
            return "running";
        case ProgramState::FeedHold:
            return "feed hold: Start continues";
        case ProgramState::ProgrammedStop:
            return "programmed stop (M00/M01): Start continues";
        case ProgramState::SingleBlock:
            return "single block: Start runs the next block";
        case ProgramState::WaitingForAxis:
            return "waiting for an axis (GAX)";
        case ProgramState::WaitingForSps:
            return "NC program restart: waiting for the SPS";
        case ProgramState::Restart:
            return "NC program restart active";
        case ProgramState::Error:
            return "stopped by an error";
    }
    return "";
}

const char* programStateWord(ProgramState state) {
    switch (state) {
        case ProgramState::NoProgram:
        case ProgramState::Ready:
            return "";
        case ProgramState::Running:
            return "running";
        case ProgramState::FeedHold:
            return "feed hold";
        case ProgramState::ProgrammedStop:
            return "M00 stop";
        case ProgramState::SingleBlock:
            return "single block";
        case ProgramState::WaitingForAxis:
        case ProgramState::WaitingForSps:
            return "waiting";
        case ProgramState::Restart:
            return "restart";
        case ProgramState::Error:
            return "error";
    }
    return "";
}

std::uint32_t blockIndexAtLine(const Program& program, int line) {
    const std::size_t count = program.blocks.size();
    std::size_t low = 0, high = count;  // first block whose line is > `line`
    while (low < high) {
        const std::size_t mid = low + (high - low) / 2;
        if (static_cast<int>(program.blocks[mid].line) <= line)
            low = mid + 1;
        else
            high = mid;
    }
    return static_cast<std::uint32_t>(low == 0 ? 0 : low - 1);
}

StationStatus describeStation(const Station& station, int around) {
    StationStatus status;
    const ModalState& modal = shownModalState(station);
    describeAxes(station, status);
    describeSpindles(station, status);
    status.programmedFeed = modal.feed;
    status.feedPerRevolution = modal.g[kGroupFeedType] == 95;
    status.actualFeed = station.machine().actualFeed();
    status.feedOverride = station.machine().feedOverride();
    status.rapidOverride = station.machine().rapidOverride();
    for (int group : usedGGroups()) {
        const int code = modal.g[static_cast<std::size_t>(group)];
        if (code >= 0) status.gFunctions.push_back({group, code, gGroupName(group).brief});
    }
    describeTool(station, status);
    status.zeroOffset = modal.g[kGroupZeroOffset];
    describeBlocks(station, around, status);
    status.state = programStateOf(station);
    return status;
}

}  // namespace mtc::core
