#include "cnc_core/interp/BlockDecoder.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "cnc_core/interp/ModalGroups.h"
#include "cnc_core/text/Numbers.h"

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

namespace {

/// The message of an assignment to a variable that does not exist, out of
/// line: built in place, it gave assignment() a large frame.
[[gnu::cold, gnu::noinline]] std::string noSuchVariableText(int index) {
    return "variable @" + std::to_string(index) + " does not exist (0.." +
           std::to_string(kVariableCount - 1) + ")";
}

}  // namespace

bool BlockDecoder::decode(const Block& block) const {
    if (t_.shortcuts && !t_.input.special)
        t_.input.clearUsual();
    else
        t_.input.clear();
    const WordList& words = t_.program.words;
    const std::size_t end =
        std::min<std::size_t>(std::size_t{block.firstWord} + block.wordCount, words.size());
    bool ok = true;
    NumberWord w;
    for (std::size_t i = block.firstWord; i < end; ++i) {
        // Most words are plain numbers in the 8-byte form: no Word is built
        // for them, and the usual kinds go to their handlers from here (so
        // that an LTO build inlines them as well).
        bool good = true;
        if (!words.readNumber(i, w))
            good = wholeWord(static_cast<std::uint32_t>(i));
        else if (w.kind == WordKind::Axis)
            good = axisWord(w);
        else if (w.kind == WordKind::G)
            good = gWord(w);
        else
            good = numberWord(w);
        if (!good) ok = false;
    }
    return ok;
}

bool BlockDecoder::wholeWord(std::uint32_t index) const {
    t_.input.special = true;
    Word w;
    t_.program.words.read(index, w);
    switch (w.kind) {
        case WordKind::Assign:
            return assignment(w);
        case WordKind::AssignMTD:
            return machineDataAssignment(w);
        case WordKind::Jump:
            return jumpWord(w, index);
        case WordKind::Command:
            return commandWord(w, index);
        default:
            return numberWord(numberWordOf(w));
    }
}

inline bool BlockDecoder::numberWord(const NumberWord& w) const {
    switch (w.kind) {
        case WordKind::G:
            return gWord(w);
        case WordKind::Axis:
            return axisWord(w);
        case WordKind::CircleCenter:
            return centerWord(w);
        case WordKind::M:
        case WordKind::Q:
            return auxWord(w);
        case WordKind::S:
            return spindleWord(w);
        case WordKind::T:
        case WordKind::E:
        case WordKind::F:
        case WordKind::D:
        case WordKind::EffectiveRadius:
            return scalarWord(w);
        default:
            return error(w.column, "UNKNOWN_WORD", "unknown word");
    }
}

inline bool BlockDecoder::gWord(const NumberWord& w) const {
    double v = 0;
    int number = 0;
    if (!value(w, v) || !integer(w.column, v, number, "G")) return false;
    const GCodeInfo info = gCodeInfo(number);
    BlockInput& in = t_.input;
    if (info.kind == GKind::Modal) {
        auto& slot = in.g[static_cast<size_t>(info.group)];
        if (slot >= 0 && slot != number) return badG(w.column, number, info, slot);
        slot = static_cast<std::int16_t>(number);
        in.gColumn[static_cast<size_t>(info.group)] = w.column;
        in.gMask |= 1u << info.group;
        return true;
    }
    in.special = true;
    if (info.kind == GKind::Dwell) {
        in.dwell = true;
        in.dwellColumn = w.column;
        return true;
    }
    if (info.kind == GKind::SpeedLimit) {
        in.speedLimit = true;
        return true;
    }
    if (info.kind == GKind::AxisFunction) {
        if (in.axisFunction != 0 && in.axisFunction != number)
            return axisFunctionConflict(w.column, number);
        in.axisFunction = static_cast<std::uint8_t>(number);
        in.axisFunctionColumn = w.column;
        return true;
    }
    if (info.kind == GKind::AdaptiveFeed) {
        if (in.adaptiveFeed != 0 && in.adaptiveFeed != number)
            return error(w.column, "G_GROUP_CONFLICT", "G25 and G26 cannot share a block");
        in.adaptiveFeed = static_cast<std::uint8_t>(number);
        in.adaptiveFeedColumn = w.column;
        return true;
    }
    return badG(w.column, number, info, -1);
}

inline bool BlockDecoder::axisWord(const NumberWord& w) const {
    const AxisLookup found = names_.find(w.letter, w.axisIndex);
    // The lookup is not handed to the cold path (it looks again): passing
    // it kept the 8-byte pair packed on the stack for every axis word.
    if (found.status != AxisNameStatus::Ok && !unusualAxisName(w)) return false;
    double v = 0;
    if (!value(w, v)) return false;
    BlockInput& in = t_.input;
    if (in.axisCount == BlockInput::kMaxAxisWords)
        return error(w.column, "TOO_MANY_AXES", "more than 16 axis words in one block");
    const auto axis = static_cast<size_t>(found.axis);
    const auto bit = static_cast<std::uint16_t>(1u << found.axis);
    if ((in.axisMask & bit) && in.repeatedAxisColumn == 0)
        in.repeatedAxisColumn = w.column;  // reported by the executor (G20 or not)
    in.axisMask |= bit;
    in.axisValue[axis] = v;
    in.axisColumn[axis] = w.column;
    const auto slot = static_cast<size_t>(in.axisCount++);
    in.axisOrder[slot] = static_cast<std::uint8_t>(found.axis);
    in.orderValue[slot] = v;
    in.orderColumn[slot] = w.column;
    return true;
}

inline bool BlockDecoder::centerWord(const NumberWord& w) const {
    const int slot = w.letter - 'I';  // I J K
    if (slot < 0 || slot > 2)
        return error(w.column, "UNKNOWN_WORD", "unknown interpolation parameter");
    double v = 0;
    if (!value(w, v)) return false;
    BlockInput& in = t_.input;
    const auto bit = static_cast<std::uint8_t>(1u << slot);
    if (in.centerMask & bit) {
        static constexpr const char* kLetters[3] = {"I", "J", "K"};
        return twice(w.column, kLetters[slot]);
    }
    in.centerMask |= bit;
    in.center[static_cast<size_t>(slot)] = v;
    in.centerColumn = w.column;
    return true;
}

inline bool BlockDecoder::auxWord(const NumberWord& w) const {
    const bool isM = w.kind == WordKind::M;
    t_.input.special = true;
    double v = 0;
    int number = 0;
    if (!value(w, v) || !integer(w.column, v, number, isM ? "M" : "Q")) return false;
    int& count = isM ? t_.input.mCount : t_.input.qCount;
    if (count == BlockInput::kMaxAux)
        return error(w.column, "TOO_MANY_AUX", "more than 8 M or Q functions in one block");
    (isM ? t_.input.m : t_.input.q)[static_cast<size_t>(count++)] = {number, w.column};
    return true;
}

inline bool BlockDecoder::spindleWord(const NumberWord& w) const {
    t_.input.special = true;
    double v = 0;
    if (!value(w, v)) return false;
    const int slot = w.axisIndex;  // 0 = S without index (reference spindle)
    if (slot != 0 && axes_.spindleAxis(slot) < 0) return noSpindle(w.column, slot);
    const auto bit = static_cast<std::uint8_t>(1u << slot);
    if (t_.input.spindleMask & bit) return twice(w.column, "spindle speed");
    if (v < 0) return error(w.column, "VALUE_RANGE", "a spindle speed cannot be negative");
    if (t_.input.spindleMask == 0) t_.input.spindleColumn = w.column;
    t_.input.spindleMask |= bit;
    t_.input.spindle[static_cast<size_t>(slot)] = v;
    return true;
}

inline bool BlockDecoder::scalarWord(const NumberWord& w) const {
    double v = 0;
    if (!value(w, v)) return false;
    BlockInput& in = t_.input;
    if (w.kind != WordKind::F) in.special = true;  // F alone keeps a block usual
    switch (w.kind) {
        case WordKind::T:
            if (in.hasTool) return twice(w.column, "T");
            in.hasTool = true;
            in.toolColumn = w.column;
            return integer(w.column, v, in.tool, "T");
        case WordKind::E:
            if (in.hasEdge) return twice(w.column, "E");
            in.hasEdge = true;
            return integer(w.column, v, in.edge, "E");
        case WordKind::D:
            if (in.hasCorrection) return twice(w.column, "D");
            in.hasCorrection = true;
            return integer(w.column, v, in.correction, "D");
        case WordKind::F:
            if (in.hasFeed) return twice(w.column, "F");
            if (v < 0) return error(w.column, "VALUE_RANGE", "F cannot be negative");
            in.hasFeed = true;
            in.feed = v;
            in.feedColumn = w.column;
            return true;
        default:
            if (in.hasRadius) return twice(w.column, "RI");
            in.hasRadius = true;
            in.radius = v;
            in.radiusColumn = w.column;
            return true;
    }
}

bool BlockDecoder::assignment(const Word& w) const {
    const auto& nodes = t_.program.expressions;
    if (w.target < 0 || static_cast<size_t>(w.target) >= nodes.size() ||
        nodes[static_cast<size_t>(w.target)].op != ExprOp::Variable)
        return error(w.column, "EXPRESSION_MALFORMED", "assignment without a variable");
    const ExprNode& target = nodes[static_cast<size_t>(w.target)];
    if (target.index < 0 || target.index >= kVariableCount)
        return error(w.column, "VARIABLE_RANGE", noSuchVariableText(target.index).c_str());
    double v = 0;
    if (!value(w, v)) return false;
    BlockInput& in = t_.input;
    if (in.writeCount == BlockInput::kMaxWrites)
        return error(w.column, "TOO_MANY_ASSIGNMENTS", "more than 16 assignments in one block");
    in.writes[static_cast<size_t>(in.writeCount++)] = {target.process, target.index, v};
    in.conditionSet = true;
    in.condition = v;
    return true;
}

bool BlockDecoder::machineDataAssignment(const Word& w) const {
    const auto& nodes = t_.program.expressions;
    if (w.target < 0 || static_cast<size_t>(w.target) >= nodes.size() ||
        nodes[static_cast<size_t>(w.target)].op != ExprOp::ReadMTD)
        return error(w.column, "EXPRESSION_MALFORMED", "MTD assignment without MTD(...)");
    BlockInput::MtdWrite write;
    EvaluationError e;
    if (!evaluator_.machineDataAddress(t_.program, nodes[static_cast<size_t>(w.target)],
                                       write.address, e))
        return error(w.column, e.code, e.message);
    if (!value(w, write.value)) return false;
    BlockInput& in = t_.input;
    if (in.mtdCount == BlockInput::kMaxMtdWrites)
        return error(w.column, "TOO_MANY_ASSIGNMENTS", "more than 4 MTD assignments in one block");
    write.column = w.column;
    in.mtdWrites[static_cast<size_t>(in.mtdCount++)] = write;
    in.conditionSet = true;
    in.condition = write.value;
    return true;
}

bool BlockDecoder::jumpWord(const Word& w, std::uint32_t index) const {
    if (t_.input.jumpWord >= 0)
        return error(w.column, "JUMP_TWICE", "only one jump, branch or call per block");
    t_.input.jumpWord = index;
    if (w.jump != JumpKind::JSR && w.jump != JumpKind::JMP && w.jump != JumpKind::JEV) return true;
    double v = 0;
    int number = 0;
    if (!value(w, v) || !integer(w.column, v, number, "program number")) return false;
    t_.input.jumpProgram = number;
    return true;
}

bool BlockDecoder::commandWord(const Word& w, std::uint32_t index) const {
    const std::string_view text = t_.program.text(w.text);
    if (text == "ITM") {
        t_.input.idleMeasurement = true;
        t_.input.idleColumn = w.column;
        return true;
    }
    if (text.substr(0, 3) == "AXD" && text.find("P-7-3651") != std::string_view::npos)
        return stallRecording(w);
    if (t_.input.commandCount == BlockInput::kMaxCommands)
        return error(w.column, "TOO_MANY_COMMANDS", "more than 4 commands in one block");
    if (w.flags & kWordNeedsCompiler)
        return error(w.column, "NEEDS_COMPILER",
                     "'" + std::string(t_.program.text(w.text)) +
                         "' is an NC compiler function; compile the program before running it");
    t_.input.commands[static_cast<size_t>(t_.input.commandCount++)] = index;
    return true;
}

bool BlockDecoder::stallRecording(const Word& w) const {
    // "(AXIS:P-7-3651)=VALUE", VALUE a number or @n of this process.
    const std::string args(t_.program.text(w.args));
    const auto colon = args.find(':');
    const auto close = args.find(')');
    const auto equals = args.find('=');
    if (args.empty() || args[0] != '(' || colon == std::string::npos ||
        close == std::string::npos || equals == std::string::npos || colon > close ||
        close > equals)
        return error(w.column, "AXD_SYNTAX",
                     "stall torque recording is written AXD(axis:P-7-3651)=period");
    std::string axis = args.substr(1, colon - 1);
    axis.erase(std::remove(axis.begin(), axis.end(), ' '), axis.end());
    if (axis == "S") axis = "S1";
    std::string value = args.substr(equals + 1);
    value.erase(std::remove(value.begin(), value.end(), ' '), value.end());
    double period = 0;
    char* end = nullptr;
    if (!value.empty() && value[0] == '@') {
        const long n = std::strtol(value.c_str() + 1, &end, 10);
        if (*end != '\0' || n < 0 || n >= kVariableCount)
            return error(w.column, "AXD_SYNTAX", "the period must be a number or a variable @n");
        EvaluationError failure;
        if (!evaluator_.readVariable(-1, static_cast<int>(n), period, failure))
            return error(w.column, failure.code, failure.message);
    } else {
        if (value.empty() || readNumberPrefix(value, period) != value.size())
            return error(w.column, "AXD_SYNTAX", "the period must be a number or a variable @n");
    }
    if (axis.empty() || axis.size() > 3)
        return error(w.column, "AXD_SYNTAX", "AXD needs an axis designation before ':'");
    BlockInput& in = t_.input;
    in.stallRecording = true;
    in.stallAxis.fill('\0');
    std::copy(axis.begin(), axis.end(), in.stallAxis.begin());
    in.stallPeriodMs = period;
    in.stallColumn = w.column;
    return true;
}

// ------------------------------------------------------------------ error paths

bool BlockDecoder::error(std::uint16_t column, const std::string& code,
                         const std::string& message) const {
    t_.diagnostics.error(code, blockLocation(t_.program, t_.blockIndex, column), message);
    return false;
}

bool BlockDecoder::error(std::uint16_t column, const char* code, const char* message) const {
    return error(column, std::string(code), std::string(message));
}

bool BlockDecoder::evaluated(std::int32_t expr, std::uint16_t column, double& out) const {
    EvaluationError e;
    if (evaluator_.evaluate(t_.program, expr, out, e)) return true;
    return error(column, e.code, e.message);
}

bool BlockDecoder::notInteger(std::uint16_t column, double v, const char* what) const {
    return error(column, "NOT_AN_INTEGER",
                 std::string(what) + " needs a whole number >= 0, got " + std::to_string(v));
}

bool BlockDecoder::twice(std::uint16_t column, std::string_view what) const {
    return error(column, "WORD_TWICE", std::string(what) + " programmed twice in one block");
}

bool BlockDecoder::axisFunctionConflict(std::uint16_t column, int number) const {
    return error(column, "G_GROUP_CONFLICT",
                 "G" + std::to_string(t_.input.axisFunction) + " and G" + std::to_string(number) +
                     " cannot share a block");
}

bool BlockDecoder::noSpindle(std::uint16_t column, int slot) const {
    return error(
        column, "AXIS_UNKNOWN",
        "S" + std::to_string(slot) + ": this process has no spindle " + std::to_string(slot));
}

bool BlockDecoder::badG(std::uint16_t column, int number, const GCodeInfo& info, int other) const {
    const std::string name = "G" + std::to_string(number);
    if (info.kind == GKind::Unknown)
        return error(column, "UNKNOWN_G", name + " is not a G function");
    if (info.kind == GKind::Unsupported)
        return error(column, "G_NOT_SUPPORTED", name + " is not executed by this simulator");
    return error(column, "G_GROUP_CONFLICT",
                 name + " and G" + std::to_string(other) + " belong to the same group " +
                     std::to_string(info.group));
}

bool BlockDecoder::unusualAxisName(NumberWord w) const {
    const AxisLookup found = names_.find(w.letter, w.axisIndex);
    if (found.status != AxisNameStatus::TransformedLinear) return badAxis(w, found);
    designationOneWarning(w, found);
    return true;
}

bool BlockDecoder::badAxis(NumberWord w, AxisLookup found) const {
    const std::string written = AxisName{w.letter, w.axisIndex}.toString();
    switch (found.status) {
        case AxisNameStatus::InactiveDesignation2:
            return error(w.column, "AXIS_DESIGNATION2_INACTIVE",
                         written +
                             " is an axis designation 2; it is valid only while G31 or "
                             "G32 is active");
        case AxisNameStatus::TransformedRotary:
            return error(w.column, "AXIS_TRANSFORMED",
                         written + " spans the transformed plane; use its axis designation 2 " +
                             axes_.axis(found.axis).designation2.toString());
        default:
            return error(w.column, "AXIS_UNKNOWN", "this process has no axis " + written);
    }
}

void BlockDecoder::designationOneWarning(NumberWord w, AxisLookup found) const {
    t_.diagnostics.warning(
        "AXIS_DESIGNATION1_IN_TRANSFORMATION", blockLocation(t_.program, t_.blockIndex, w.column),
        AxisName{w.letter, w.axisIndex}.toString() +
            " is written with designation 1 while G31/G32 renames it to " +
            axes_.axis(found.axis).designation2.toString() + "; taken as that axis");
}

}  // namespace mtc::core
