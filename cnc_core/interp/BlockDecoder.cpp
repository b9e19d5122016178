#include "cnc_core/interp/BlockDecoder.h"

#include <cmath>

#include "cnc_core/interp/ModalGroups.h"

namespace mtc::core {

SourceLocation blockLocation(const Program& program, std::uint32_t blockIndex, int column) {
    SourceLocation where;
    where.program = program.number;
    if (blockIndex < program.blocks.size()) {
        where.block = program.blockId(blockIndex);
        where.line = static_cast<int>(program.blocks[blockIndex].line);
    }
    where.column = column;
    return where;
}

bool BlockDecoder::decode(const Program& program, const Block& block, std::uint32_t blockIndex,
                          BlockInput& input, DiagnosticList& diagnostics) const {
    input.clear();
    const std::size_t end =
        std::min<std::size_t>(block.firstWord + block.wordCount, program.words.size());
    bool ok = true;
    for (std::size_t i = block.firstWord; i < end; ++i) {
        const Word w = program.words[i];
        Cursor c{program, blockIndex, static_cast<std::uint32_t>(i), w, input, diagnostics};
        if (!word(c)) ok = false;
    }
    return ok;
}

bool BlockDecoder::error(Cursor& c, const std::string& code, const std::string& message) const {
    c.diagnostics.error(code, blockLocation(c.program, c.blockIndex, c.word.column), message);
    return false;
}

bool BlockDecoder::evaluated(Cursor& c, double& out) const {
    EvaluationError e;
    if (evaluator_.evaluate(c.program, c.word.expr, out, e)) return true;
    return error(c, e.code, e.message);
}

bool BlockDecoder::notInteger(Cursor& c, double v, const char* what) const {
    return error(c, "NOT_AN_INTEGER",
                 std::string(what) + " needs a whole number >= 0, got " + std::to_string(v));
}

bool BlockDecoder::word(Cursor& c) const {
    switch (c.word.kind) {
        case WordKind::G:
            return gWord(c);
        case WordKind::M:
        case WordKind::Q:
            return auxWord(c);
        case WordKind::S:
            return spindleWord(c);
        case WordKind::T:
        case WordKind::E:
        case WordKind::F:
        case WordKind::D:
        case WordKind::EffectiveRadius:
            return scalarWord(c);
        case WordKind::Axis:
            return axisWord(c);
        case WordKind::CircleCenter:
            return centerWord(c);
        case WordKind::Assign:
            return assignment(c);
        case WordKind::AssignMTD:
            return machineDataAssignment(c);
        case WordKind::Jump:
            return jumpWord(c);
        case WordKind::Command:
            return commandWord(c);
    }
    return error(c, "UNKNOWN_WORD", "unknown word");
}

bool BlockDecoder::gWord(Cursor& c) const {
    double v = 0;
    int number = 0;
    if (!value(c, v) || !integer(c, v, number, "G")) return false;
    const GCodeInfo info = gCodeInfo(number);
    auto name = [number] { return "G" + std::to_string(number); };
    switch (info.kind) {
        case GKind::Unknown:
            return error(c, "UNKNOWN_G", name() + " is not a G function");
        case GKind::Unsupported:
            return error(c, "G_NOT_SUPPORTED", name() + " is not executed by this simulator");
        case GKind::Dwell:
            c.input.dwell = true;
            c.input.dwellColumn = c.word.column;
            return true;
        case GKind::SpeedLimit:
            c.input.speedLimit = true;
            return true;
        case GKind::Modal:
            break;
    }
    auto& slot = c.input.g[static_cast<size_t>(info.group)];
    if (slot >= 0 && slot != number)
        return error(c, "G_GROUP_CONFLICT",
                     name() + " and G" + std::to_string(slot) + " belong to the same group " +
                         std::to_string(info.group));
    slot = static_cast<std::int16_t>(number);
    c.input.gColumn[static_cast<size_t>(info.group)] = c.word.column;
    return true;
}

bool BlockDecoder::auxWord(Cursor& c) const {
    const bool isM = c.word.kind == WordKind::M;
    double v = 0;
    int number = 0;
    if (!value(c, v) || !integer(c, v, number, isM ? "M" : "Q")) return false;
    int& count = isM ? c.input.mCount : c.input.qCount;
    if (count == BlockInput::kMaxAux)
        return error(c, "TOO_MANY_AUX", "more than 8 M or Q functions in one block");
    (isM ? c.input.m : c.input.q)[static_cast<size_t>(count++)] = {number, c.word.column};
    return true;
}

bool BlockDecoder::spindleWord(Cursor& c) const {
    double v = 0;
    if (!value(c, v)) return false;
    const int spindle = c.word.axisIndex == 0 ? 0 : c.word.axisIndex;
    const int slot = spindle == 0 ? 0 : spindle;
    if (spindle != 0 && axes_.spindleAxis(spindle) < 0)
        return error(c, "AXIS_UNKNOWN",
                     "S" + std::to_string(spindle) + ": this process has no spindle " +
                         std::to_string(spindle));
    const auto bit = static_cast<std::uint8_t>(1u << slot);
    if (c.input.spindleMask & bit) return error(c, "WORD_TWICE", "spindle speed programmed twice");
    if (v < 0) return error(c, "VALUE_RANGE", "a spindle speed cannot be negative");
    c.input.spindleMask |= bit;
    c.input.spindle[static_cast<size_t>(slot)] = v;
    return true;
}

bool BlockDecoder::scalarWord(Cursor& c) const {
    double v = 0;
    if (!value(c, v)) return false;
    BlockInput& in = c.input;
    auto once = [&](bool& flag, const char* name) {
        if (flag)
            return error(c, "WORD_TWICE", std::string(name) + " programmed twice in one block");
        flag = true;
        return true;
    };
    switch (c.word.kind) {
        case WordKind::T:
            in.toolColumn = c.word.column;
            return once(in.hasTool, "T") && integer(c, v, in.tool, "T");
        case WordKind::E:
            return once(in.hasEdge, "E") && integer(c, v, in.edge, "E");
        case WordKind::D:
            return once(in.hasCorrection, "D") && integer(c, v, in.correction, "D");
        case WordKind::F:
            if (!once(in.hasFeed, "F")) return false;
            if (v < 0) return error(c, "VALUE_RANGE", "F cannot be negative");
            in.feed = v;
            in.feedColumn = c.word.column;
            return true;
        default:
            if (!once(in.hasRadius, "RI")) return false;
            in.radius = v;
            in.radiusColumn = c.word.column;
            return true;
    }
}

bool BlockDecoder::axisWord(Cursor& c) const {
    const AxisLookup found = names_.find(c.word.letter, c.word.axisIndex);
    AxisName written{c.word.letter, c.word.axisIndex};
    switch (found.status) {
        case AxisNameStatus::Unknown:
            return error(c, "AXIS_UNKNOWN", "this process has no axis " + written.toString());
        case AxisNameStatus::InactiveDesignation2:
            return error(c, "AXIS_DESIGNATION2_INACTIVE",
                         written.toString() +
                             " is an axis designation 2; it is valid only while "
                             "G31 or G32 is active");
        case AxisNameStatus::TransformedRotary:
            return error(c, "AXIS_TRANSFORMED",
                         written.toString() +
                             " spans the transformed plane; use its axis "
                             "designation 2 " +
                             axes_.axis(found.axis).designation2.toString());
        case AxisNameStatus::TransformedLinear:
            c.diagnostics.warning(
                "AXIS_DESIGNATION1_IN_TRANSFORMATION",
                blockLocation(c.program, c.blockIndex, c.word.column),
                written.toString() + " is written with designation 1 while G31/G32 renames it to " +
                    axes_.axis(found.axis).designation2.toString() + "; taken as that axis");
            break;
        case AxisNameStatus::Ok:
            break;
    }
    double v = 0;
    if (!value(c, v)) return false;
    const auto bit = static_cast<std::uint16_t>(1u << found.axis);
    if (c.input.axisCount == BlockInput::kMaxAxisWords)
        return error(c, "TOO_MANY_AXES", "more than 16 axis words in one block");
    if ((c.input.axisMask & bit) && c.input.repeatedAxisColumn == 0)
        c.input.repeatedAxisColumn = c.word.column;  // reported by the executor (G20 or not)
    c.input.axisMask |= bit;
    c.input.axisValue[static_cast<size_t>(found.axis)] = v;
    c.input.axisColumn[static_cast<size_t>(found.axis)] = c.word.column;
    const auto slot = static_cast<size_t>(c.input.axisCount++);
    c.input.axisOrder[slot] = static_cast<std::int8_t>(found.axis);
    c.input.orderValue[slot] = v;
    c.input.orderColumn[slot] = c.word.column;
    return true;
}

bool BlockDecoder::centerWord(Cursor& c) const {
    const int slot = c.word.letter == 'I'   ? 0
                     : c.word.letter == 'J' ? 1
                     : c.word.letter == 'K' ? 2
                                            : -1;
    if (slot < 0) return error(c, "UNKNOWN_WORD", "unknown interpolation parameter");
    double v = 0;
    if (!value(c, v)) return false;
    const auto bit = static_cast<std::uint8_t>(1u << slot);
    if (c.input.centerMask & bit)
        return error(c, "WORD_TWICE", std::string(1, c.word.letter) + " programmed twice");
    c.input.centerMask |= bit;
    c.input.center[static_cast<size_t>(slot)] = v;
    c.input.centerColumn = c.word.column;
    return true;
}

bool BlockDecoder::assignment(Cursor& c) const {
    if (c.word.target < 0 || static_cast<size_t>(c.word.target) >= c.program.expressions.size() ||
        c.program.expressions[static_cast<size_t>(c.word.target)].op != ExprOp::Variable)
        return error(c, "EXPRESSION_MALFORMED", "assignment without a variable");
    const ExprNode& target = c.program.expressions[static_cast<size_t>(c.word.target)];
    if (target.index < 0 || target.index >= kVariableCount)
        return error(c, "VARIABLE_RANGE",
                     "variable @" + std::to_string(target.index) + " does not exist (0.." +
                         std::to_string(kVariableCount - 1) + ")");
    double v = 0;
    if (!value(c, v)) return false;
    if (c.input.writeCount == BlockInput::kMaxWrites)
        return error(c, "TOO_MANY_ASSIGNMENTS", "more than 16 assignments in one block");
    c.input.writes[static_cast<size_t>(c.input.writeCount++)] = {target.process, target.index, v};
    c.input.conditionSet = true;
    c.input.condition = v;
    return true;
}

bool BlockDecoder::machineDataAssignment(Cursor& c) const {
    if (c.word.target < 0 || static_cast<size_t>(c.word.target) >= c.program.expressions.size() ||
        c.program.expressions[static_cast<size_t>(c.word.target)].op != ExprOp::ReadMTD)
        return error(c, "EXPRESSION_MALFORMED", "MTD assignment without MTD(...)");
    BlockInput::MtdWrite w;
    EvaluationError e;
    if (!evaluator_.machineDataAddress(
            c.program, c.program.expressions[static_cast<size_t>(c.word.target)], w.address, e))
        return error(c, e.code, e.message);
    if (!value(c, w.value)) return false;
    if (c.input.mtdCount == BlockInput::kMaxMtdWrites)
        return error(c, "TOO_MANY_ASSIGNMENTS", "more than 4 MTD assignments in one block");
    w.column = c.word.column;
    c.input.mtdWrites[static_cast<size_t>(c.input.mtdCount++)] = w;
    c.input.conditionSet = true;
    c.input.condition = w.value;
    return true;
}

bool BlockDecoder::jumpWord(Cursor& c) const {
    if (c.input.jumpWord >= 0)
        return error(c, "JUMP_TWICE", "only one jump, branch or call per block");
    c.input.jumpWord = c.wordIndex;
    const JumpKind k = c.word.jump;
    if (k != JumpKind::JSR && k != JumpKind::JMP && k != JumpKind::JEV) return true;
    double v = 0;
    if (!value(c, v)) return false;
    int number = 0;
    if (!integer(c, v, number, "program number")) return false;
    c.input.jumpProgram = number;
    return true;
}

bool BlockDecoder::commandWord(Cursor& c) const {
    if (c.input.commandCount == BlockInput::kMaxCommands)
        return error(c, "TOO_MANY_COMMANDS", "more than 4 commands in one block");
    if (c.word.flags & kWordNeedsCompiler)
        return error(c, "NEEDS_COMPILER",
                     "'" + std::string(c.program.text(c.word.text)) +
                         "' is an NC compiler function; compile the program before running it");
    c.input.commands[static_cast<size_t>(c.input.commandCount++)] = c.wordIndex;
    return true;
}

}  // namespace mtc::core
