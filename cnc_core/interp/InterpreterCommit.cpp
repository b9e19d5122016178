// Interpreter, second half: committing a checked block (state, outputs
// through the sink, program flow) and the program-end / reset rules.
#include <cmath>
#include <cstring>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/text/Digits.h"

namespace mtc::core {
namespace {

/// Writes `value` with at least four digits at `out` (0..99,999,999); returns the end.
char* fourDigits(int value, char* out) {
    if (value < 10000) {
        writeFourDigits(out, value);
        return out + 4;
    }
    char reversed[12];
    int count = 0;
    do {
        reversed[count++] = static_cast<char>('0' + value % 10);
        value /= 10;
    } while (value > 0 && count < 11);
    while (count > 0)
        *out++ = reversed[--count];
    return out;
}

/// formatBlockId() for every case but the usual one.
[[gnu::noinline]] void formatBlockIdInFull(const Block& block, std::string& out) {
    const int number = block.number;
    if (number < 0) {
        out.clear();
        return;
    }
    if (number < 10000 && block.subNumber < 0) {
        out.assign(5, 'N');
        writeFourDigits(&out[1], number);
        return;
    }
    char text[32];
    char* end = text;
    *end++ = 'N';
    end = fourDigits(number, end);
    if (block.subNumber >= 0) {
        *end++ = ':';
        end = fourDigits(block.subNumber, end);
    }
    out.assign(text, static_cast<std::size_t>(end - text));
}

/// "N0012" / "N0012:0001" into `out` without printf (called once per move).
/// The usual case, a four-digit number over the last one, is written in place.
inline void formatBlockId(const Block& block, std::string& out) {
    const int number = block.number;
    if (number >= 0 && number < 10000 && block.subNumber < 0 && out.size() == 5) {
        out[0] = 'N';
        writeFourDigits(&out[1], number);
        return;
    }
    formatBlockIdInFull(block, out);
}

/// The G groups the frame fields of a move follow (zero offset, radius /
/// diameter, G6/G7, G8/G9), packed into one number.
std::uint64_t frameGroups(const GGroupValues& g) {
    auto bits = [&](int group) {
        return static_cast<std::uint64_t>(
            static_cast<std::uint16_t>(g[static_cast<std::size_t>(group)]));
    };
    return bits(kGroupZeroOffset) | bits(kGroupRadiusDiameter) << 16 |
           bits(kGroupAcceleration) << 32 | bits(kGroupExactStop) << 48;
}

/// What the move's fields take from a transformation: kind, plane axes and
/// the effective radius's bits, packed.
std::array<std::uint64_t, 2> transformationKey(const Transformation& t) {
    std::uint64_t radius = 0;
    const double r = t.effectiveRadius();
    std::memcpy(&radius, &r, sizeof radius);
    const auto small = [](int v) {
        return static_cast<std::uint64_t>(static_cast<std::uint16_t>(v));
    };
    return {radius, small(t.kind()) | small(t.planeAxis(0)) << 16 | small(t.planeAxis(1)) << 32};
}

/// True when a function of the block may go to the sink (an over-estimate
/// is harmless): only then does emitAux() build the outputs' location.
bool auxForwarded(const BlockInput& in, const OutputOptions& out) {
    return (out.s && in.spindleMask != 0) || (out.te && (in.hasTool || in.hasEdge)) ||
           (out.m && in.mCount > 0) || (out.q && in.qCount > 0);
}

}  // namespace

SourceLocation Interpreter::sinkLocation(const Program& program, std::uint32_t /*index*/) const {
    SourceLocation where;
    where.program = program.number;
    formatBlockId(block_, where.block);
    where.line = static_cast<int>(block_.line);
    return where;
}

Interpreter::Outcome Interpreter::commit(const Program& program, std::uint32_t index,
                                         DiagnosticList& diagnostics) {
    // Moves go to tool compensation also when they are not sent: it follows the axes.
    const bool motion = plan_.hasMotion && (options_.output.motion || compensation_.planned());
    const bool transformationChanged = commitModalState(motion);
    for (int i = 0; i < input_.writeCount; ++i) {
        const auto& w = input_.writes[static_cast<size_t>(i)];
        if (w.process >= 0 && w.process != config_.index) {
            otherProcesses_->write(w.process, w.index, w.value);
            continue;
        }
        state_.variables.values[static_cast<size_t>(w.index)] = w.value;
        state_.variables.written.set(static_cast<size_t>(w.index));
    }
    for (int i = 0; i < input_.mtdCount; ++i)
        machineData_->write(input_.mtdWrites[static_cast<size_t>(i)].address,
                            input_.mtdWrites[static_cast<size_t>(i)].value, MachineDataWriter::Nc);
    if (input_.conditionSet) state_.condition = input_.condition;
    if (plan_.auxChanged) {
        state_.mGroups = plan_.mGroups;
        state_.lastQ = plan_.lastQ;
    }
    if (transformationChanged) rebuildNames();
    if (compensation_.planned()) compensation_.beginOutputs(options_.output.motion);
    const BlockInput& in = input_;
    if (in.spindleMask != 0 || in.hasTool || in.hasEdge || in.mCount != 0 || in.qCount != 0)
        emitAux(program, index);
    const bool adaptive = afcInvolved_;
    if (adaptive) commitAdaptiveFeed();
    if (motion) emitMotion(program, index);
    if (adaptive && !adaptiveFeedAfterMotion(program, diagnostics)) return Outcome::Error;
    if (plan_.dwellSeconds >= 0.0 && options_.output.dwell)
        sink_.dwell(sinkLocation(program, index), plan_.dwellSeconds);
    if (input_.commandCount > 0) runCommands(program, index);
    const bool stopping =
        plan_.programControl == 0 || (plan_.programControl == 1 && options_.optionalStop);
    // A tool path that turns out to cross an earlier one at a stop: the block
    // is done, the run stops after it (check mode goes on).
    const bool compensationOk =
        !compensation_.planned() || compensation_.endBlock(stopping, diagnostics);
    switch (plan_.programControl) {
        case 2:
        case 30:
            programEnd(&diagnostics);
            return Outcome::Ended;
        default:
            break;
    }
    if (flow_.kind == FlowPlan::Kind::Next) {
        ++state_.block;
    } else {
        const Outcome flow = applyFlow(program, index, diagnostics);
        if (flow != Outcome::Continue) return flow;
    }
    if (!compensationOk && !options_.continueAfterError) return Outcome::Error;
    if (plan_.programControl == 0 || (plan_.programControl == 1 && options_.optionalStop)) {
        publishRotaryAxisModes();  // page 60 el. 1..3 "upon program stop" (seed 000, 4.1)
        return Outcome::Stopped;
    }
    return Outcome::Continue;
}

void Interpreter::sendAux(AuxOutput& out, char type, int spindle, double value, bool forwarded) {
    out.type = type;
    out.spindle = spindle;
    out.value = value;
    if (forwarded) sink_.auxiliary(out);
    if (observer_) observer_->auxiliary(out, forwarded);
}

// Inline in commit(), its only caller: one call and frame less per block with aux functions.
[[gnu::always_inline]] inline void Interpreter::emitAux(const Program& program,
                                                        std::uint32_t index) {
    const BlockInput& in = input_;
    const OutputOptions& out = options_.output;
    // One location for all functions of the block, and only when one goes to
    // the sink: an AuxObserver reads the location of forwarded outputs only
    // (the computing process's collector none; R-018), and the block id is a
    // string per block.
    AuxOutput aux;
    if (auxForwarded(in, out)) aux.where = sinkLocation(program, index);
    if (in.spindleMask != 0 && !in.speedLimit)  // most blocks with aux functions have no S
        for (int slot = 0; slot < kSpindleSlots; ++slot)
            if ((in.spindleMask >> slot) & 1u) {
                const int spindle = slot == 0 ? state_.modal.referenceSpindle : slot;
                // G77 S: the re-established speed goes to the SPS, not the placeholder.
                const double speed = in.axisFunction == 77
                                         ? state_.modal.spindleSpeed[static_cast<size_t>(spindle)]
                                         : in.spindle[static_cast<size_t>(slot)];
                sendAux(aux, 'S', spindle, speed, out.s);
            }
    if (in.hasTool) sendAux(aux, 'T', 0, in.tool, out.te);
    if (in.hasEdge) sendAux(aux, 'E', 0, in.edge, out.te);
    for (int i = 0; i < in.mCount; ++i)
        sendAux(aux, 'M', 0, in.m[static_cast<size_t>(i)].value, out.m);
    for (int i = 0; i < in.qCount; ++i)
        sendAux(aux, 'Q', 0, in.q[static_cast<size_t>(i)].value, out.q);
}

// Inline in emitMotion: asked for every move.
inline bool Interpreter::sameMotionFrame() const {
    const ModalState& now = state_.modal;
    const MotionFrame& f = motionFrame_;
    // Equal bytes are equal values; unequal bytes (-0.0 and 0.0) only recompute.
    const std::array<std::uint64_t, 2> transformation = transformationKey(now.transformation);
    return f.valid && f.groups == frameGroups(now.g) && f.transformation[0] == transformation[0] &&
           f.transformation[1] == transformation[1] &&
           std::memcmp(&f.plane, &now.plane, sizeof f.plane) == 0;
}

void Interpreter::emitMotion(const Program& program, std::uint32_t index) {
    Motion& m = motion_;
    m.blockIndex = index;
    m.where.program = program.number;
    formatBlockId(block_, m.where.block);
    m.where.line = static_cast<int>(block_.line);
    m.where.column = 0;
    m.type = plan_.motionType;
    m.end = state_.modal.machine;
    const bool arc = m.type == MotionType::ArcCW || m.type == MotionType::ArcCCW;
    m.planeAxis1 = arc ? plan_.planeAxis1 : -1;
    m.planeAxis2 = arc ? plan_.planeAxis2 : -1;
    m.center1 = arc ? plan_.center1 : 0.0;
    m.center2 = arc ? plan_.center2 : 0.0;
    m.fullCircle = arc && plan_.fullCircle;
    m.feed = plan_.feedRate;
    if (!options_.shortcuts || (!motionFrameCurrent_ && !sameMotionFrame())) {
        fillMotionFrame(m);
    } else if (m.zeroOffset != 53) {  // the table may change between two blocks
        zeroOffsetValues(m);
    }
    motionFrameCurrent_ = true;
    m.compensated = false;  // tool compensation marks the moves it changes
    m.inserted = false;
    compensation_.motion(m, options_.output.motion);
}

void Interpreter::fillMotionFrame(Motion& m) {
    const ModalState& now = state_.modal;
    MotionFrame& f = motionFrame_;
    f.groups = frameGroups(now.g);
    std::memcpy(&f.plane, &now.plane, sizeof f.plane);
    f.transformation = transformationKey(now.transformation);
    f.valid = true;
    m.axisCount = axes_.count();
    m.exactStop = state_.modal.g[kGroupExactStop] == 9;
    m.blendCorners = state_.modal.g[kGroupAcceleration] == 7;
    m.transformation = state_.modal.transformation.kind();
    m.effectiveRadius = state_.modal.transformation.effectiveRadius();
    m.transformAxis1 =
        state_.modal.transformation.active() ? state_.modal.transformation.planeAxis(0) : -1;
    m.transformAxis2 =
        state_.modal.transformation.active() ? state_.modal.transformation.planeAxis(1) : -1;
    m.zeroOffset = state_.modal.g[kGroupZeroOffset];
    zeroOffsetValues(m);
    m.radialAxis = -1;
    for (int a = 0; a < m.axisCount && m.radialAxis < 0; ++a)
        if (!axes_.axis(a).rotary && state_.modal.plane.definitionOf(a) == AxisDefinition::X)
            m.radialAxis = a;
    m.diameter = state_.modal.g[kGroupRadiusDiameter] == 16;
}

void Interpreter::zeroOffsetValues(Motion& m) const {
    // MotionPlanner::offsetOf per axis; G53 (no zero offset) is 0 for every axis.
    const int offset = m.zeroOffset;
    for (int a = 0; a < m.axisCount && a < kMaxAxes; ++a)
        m.zeroOffsetValues[static_cast<std::size_t>(a)] =
            offset == 53 ? 0.0 : zeroOffsets_->value(offset, state_.modal.plane.definitionOf(a));
}

void Interpreter::runCommands(const Program& program, std::uint32_t index) {
    const SourceLocation where = sinkLocation(program, index);
    for (int i = 0; i < input_.commandCount; ++i) {
        const Word w = program.words[input_.commands[static_cast<size_t>(i)]];
        std::optional<MachineCommand> command =
            readMachineCommand(program.text(w.text), program.text(w.args));
        if (!command) continue;  // the parser classifies only command keywords as commands
        command->where = where;
        modalChanged();
        if (const auto* transfer = std::get_if<ToolTransferCommand>(&command->action)) {
            const auto spindle = static_cast<size_t>(transfer->spindle - 1);
            state_.modal.toolSpindle[spindle] =
                command->keyword == CommandKeyword::TSM ? 0 : state_.modal.tool;
        } else if (command->keyword == CommandKeyword::MTP && config_.toolStorage == "turret") {
            state_.modal.toolSpindle[0] = state_.modal.tool;
        }
        if (const auto* transfer = std::get_if<AxisTransferCommand>(&command->action))
            if (axisTransfer_) commitAxisTransfer(*transfer);
        if (options_.output.commands) sink_.command(*command);
    }
}

Interpreter::Outcome Interpreter::applyFlow(const Program& /*program*/, std::uint32_t index,
                                            DiagnosticList& diagnostics) {
    switch (flow_.kind) {
        case FlowPlan::Kind::Next:
            ++state_.block;
            return Outcome::Continue;
        case FlowPlan::Kind::Goto:
            if (flow_.program != state_.program) state_.program = flow_.program;
            state_.block = flow_.block;
            return Outcome::Continue;
        case FlowPlan::Kind::Call:
            state_.callStack.push_back({state_.program, index, index + 1});
            state_.program = flow_.program;
            state_.block = flow_.block;
            return Outcome::Continue;
        case FlowPlan::Kind::Return: {
            CallFrame frame = std::move(state_.callStack.back());
            state_.callStack.pop_back();
            state_.program = std::move(frame.program);
            state_.block = frame.returnBlock;
            return Outcome::Continue;
        }
        case FlowPlan::Kind::End:
            programEnd(&diagnostics);
            return Outcome::Ended;
        case FlowPlan::Kind::Jump:
            resetBaseSystem();
            state_.callStack.clear();
            state_.program = flow_.program;
            state_.selected = flow_.program;
            state_.block = 0;
            return Outcome::Continue;
    }
    return Outcome::Continue;
}

void Interpreter::resetBaseSystem() {
    modalChanged();
    ModalState& m = state_.modal;
    if (m.transformation.active()) {
        m.transformation.deselect();
        m.g[kGroupTransformation] = 30;
        m.g[kGroupZeroOffset] = 53;
        m.g[kGroupRadiusDiameter] = defaults_[kGroupRadiusDiameter];
    }
    m.g[kGroupPlane] = defaults_[kGroupPlane];
    m.plane = PlaneSelection::base(axes_, defaults_[kGroupPlane]);
    MotionPlanner(&axes_, zeroOffsets_.get()).recomputeWork(m);
    rebuildNames();
}

void Interpreter::resetModal() {
    modalChanged();
    ModalState& m = state_.modal;
    m.g = defaults_;
    m.transformation.deselect();
    m.plane = PlaneSelection::base(axes_, defaults_[kGroupPlane]);
    m.spindleLimit = {};
    m.adaptiveFeed = false;  // program end switches adaptive feed control off (seed 002)
    MotionPlanner(&axes_, zeroOffsets_.get()).recomputeWork(m);
}

void Interpreter::programEnd(DiagnosticList* diagnostics) {
    compensation_.programEnd(diagnostics);  // before the frame goes back to the defaults
    resetModal();
    for (int g = 1; g <= 16; ++g)
        state_.mGroups[static_cast<size_t>(g)] = -1;
    for (const auto& group : config_.mGroups)
        if (group.number >= 1 && group.number <= 15)
            state_.mGroups[static_cast<size_t>(group.number)] = group.resetValue;
    state_.lastQ = -1;
    if (afc_) afc_->programEnd();
    state_.reentry.valid = false;
    state_.callStack.clear();
    state_.program = state_.selected;
    state_.block = 0;
    state_.ended = true;
    rebuildNames();
}

void Interpreter::controlReset() {
    if (!state_.selected) state_.selected = state_.program;
    compensation_.controlReset();
    programEnd();
    if (afc_) {  // Clear Error of the panel is the Control reset key (afc.md AFC-012)
        afc_->controlReset();
        afc_->clearError();
    }
    state_.ended = false;
    target_.reset();
    targetArrivals_ = 0;
    withdrawAxisRequests();
}

std::vector<StackLevel> Interpreter::callStack() const {
    std::vector<StackLevel> levels;
    auto level = [&](const ProgramPtr& program, std::uint32_t block) {
        StackLevel l;
        if (!program) return l;
        l.program = program->number;
        l.blockIndex = block;
        if (block < program->blocks.size()) {
            l.block = program->blockId(block);
            l.line = static_cast<int>(program->blocks[block].line);
        }
        return l;
    };
    for (const auto& frame : state_.callStack)
        levels.push_back(level(frame.program, frame.callBlock));
    if (state_.program) levels.push_back(level(state_.program, state_.block));
    return levels;
}

namespace {

/// Workpiece coordinate `v` (mm) of `axis` in the program's view of `m`.
double programUnits(const ModalState& m, const AxisModel& model, int axis, double v) {
    if (model.rotary && !m.transformation.transforms(axis)) return v;
    if (m.g[kGroupRadiusDiameter] == 16 && m.plane.definitionOf(axis) == AxisDefinition::X)
        v *= 2.0;
    v /= millimetresPerUnit(m);
    return v;
}

}  // namespace

double Interpreter::programmedPosition(int axis) const {
    return programUnits(state_.modal, axes_.axis(axis), axis,
                        state_.modal.work[static_cast<size_t>(axis)]);
}

std::array<double, kMaxAxes> Interpreter::programView(
    const std::array<double, kMaxAxes>& machine) const {
    return programView(machine, state_.modal);
}

std::array<double, kMaxAxes> Interpreter::programView(const std::array<double, kMaxAxes>& machine,
                                                      const ModalState& modal) const {
    ModalState m = modal;
    m.machine = machine;
    MotionPlanner(&axes_, zeroOffsets_.get()).recomputeWork(m);
    std::array<double, kMaxAxes> out{};
    for (int a = 0; a < axes_.count(); ++a)
        out[static_cast<size_t>(a)] =
            programUnits(m, axes_.axis(a), a, m.work[static_cast<size_t>(a)]);
    return out;
}

std::string Interpreter::programmedAxisName(int axis) const {
    return core::programmedAxisName(axes_, state_.modal.transformation, axis);
}

void Interpreter::takeMachinePositions(const std::array<double, kMaxAxes>& machine) {
    state_.modal.machine = machine;
    compensation_.restart();
    MotionPlanner(&axes_, zeroOffsets_.get()).recomputeWork(state_.modal);
    modalChanged();
}

bool Interpreter::manualJogPerformed() {
    if (!config_.flag("B036")) return false;
    controlReset();
    return true;
}

void Interpreter::publishRotaryAxisModes() {
    for (int s = 1; s <= 3; ++s)
        machineData_->write({60, config_.index, 0, s},
                            state_.modal.rotaryAxisMode[static_cast<size_t>(s)],
                            MachineDataWriter::Nc);
}

void Interpreter::publishPage60() {
    const ModalState& m = state_.modal;
    auto put = [&](int element, double value) {
        machineData_->write({60, config_.index, 0, element}, value, MachineDataWriter::Nc);
    };
    publishRotaryAxisModes();
    put(4, m.transformation.kind());
    for (int t = 0; t < kToolSpindles; ++t)
        put(5 + t, m.toolSpindle[static_cast<size_t>(t)]);
}

}  // namespace mtc::core
