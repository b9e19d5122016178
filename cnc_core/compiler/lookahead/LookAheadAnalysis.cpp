// Scan of a block sequence for the enhanced look-ahead (seed 001 ch. 6):
// look-ahead variables, LA_ON ... LA_OFF segments and their rules.
#include "cnc_core/compiler/lookahead/LookAheadAnalysis.h"

#include <cmath>
#include <optional>

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/lookahead/LookAheadScan.h"
#include "cnc_core/language/CheckedNumber.h"
#include "cnc_core/language/Keywords.h"

namespace mtc::core::lookahead {
namespace detail {

namespace {
// A T or E word beyond these matches no tool (the interpreter refuses it).
constexpr long kNoNumber = -1;
constexpr long kLongest = 999'999'999;
}  // namespace

Analyzer::Analyzer(const BlockSequence& blocks, CompileContext& context, const LookAheadDefaults& d)
    : blocks_(blocks),
      context_(context),
      defaults_(d),
      limits_(axisLimitsOf(context.options().process)) {
    const ProcessConfig* process = context.options().process;
    state_.metbMs = process ? process->number("B070", d.metbMs) : d.metbMs;
    state_.vfbt = process ? process->number("B071", d.vfbt) : d.vfbt;
    state_.bbtrc = clampedInteger(process ? process->number("B072", d.bbtrc) : d.bbtrc, 1, 10);
    blockCycleMs_ = process ? process->number("B073", d.blockCycleMs) : d.blockCycleMs;
    processIndex_ = process ? process->index : 0;
    state_.position = AxisVector::Zero(limits_.size());
    state_.known.assign(static_cast<std::size_t>(limits_.size()), true);
    for (int i = 0; i < limits_.size(); ++i)
        definitions_.push_back(definitionOf(i));
}

LookAheadAnalysis Analyzer::run() {
    const ParsedSequence& parsed = context_.parsed(blocks_);
    for (std::size_t i = 0; i < blocks_.size() && !context_.stopped(); ++i) {
        if (blocks_[i].programEnd || parsed.parsedOf[i] < 0) continue;
        const Block block = parsed.program.blocks[static_cast<std::size_t>(parsed.parsedOf[i])];
        scanBlock(i, parsed.program, block);
    }
    if (inside_ && !context_.stopped())
        report(segment_.onBlock, "LA_OFF_MISSING", "LA_ON without LA_OFF",
               {"Every LA_ON needs its LA_OFF (also in reverse programs)."});
    return std::move(result_);
}

char Analyzer::definitionOf(int axis) const {
    const ProcessConfig* process = context_.options().process;
    if (process) {
        const AxisConfig* config = process->axis(limits_.names[static_cast<std::size_t>(axis)]);
        if (config && !config->definitions.empty() && !config->definitions[0].empty())
            return config->definitions[0][0];
    }
    return limits_.names[static_cast<std::size_t>(axis)][0];
}

bool Analyzer::report(std::size_t block, std::string code, std::string message,
                      std::vector<std::string> details) {
    if (inside_) segment_.failed = true;
    return context_.reportAt(blocks_, block, Severity::Error, std::move(code), std::move(message),
                             std::move(details));
}

void Analyzer::scanBlock(std::size_t i, const Program& program, const Block& block) {
    const BlockWords words = detail::splitWords(blocks_[i], program, block);
    std::vector<bool> drop(words.raw.size(), false);
    motionBlock_ = static_cast<std::size_t>(-1);
    if (inside_ && !(block.flags & kBlockHasError)) {
        insideBlock(i, program, block, words, drop);
    } else if (!inside_) {
        outsideBlock(i, program, block, drop);
    }
    bool dropped = false;
    for (bool d : drop)
        dropped = dropped || d;
    if (!dropped || motionBlock_ == i) return;  // a motion block is rewritten by the emitter
    std::vector<std::string> kept;
    for (std::size_t k = 0; k < words.raw.size(); ++k)
        if (!drop[k]) kept.push_back(words.raw[k]);
    result_.rewrites.emplace_back(i, detail::joinWords(words.lead, kept, words.comment));
}

// ---------------------------------------------------------------- outside

void Analyzer::outsideBlock(std::size_t i, const Program& program, const Block& block,
                            std::vector<bool>& drop) {
    AxisVector target = state_.position;
    for (std::uint32_t k = 0; k < block.wordCount; ++k) {
        const Word w = program.words[block.firstWord + k];
        if (w.kind == WordKind::Command && (w.flags & kWordNeedsCompiler))
            drop[k] = compilerWordOutside(i, program, w);
        else
            modalWord(w, target);
    }
    state_.position = target;
    if (inside_ && block.wordCount > 1)
        report(i, "LA_KEYWORD_NOT_ALONE", "LA_ON must stand alone in its block");
}

/// Tracks G groups, positions, F, T and E of any word outside a segment.
void Analyzer::modalWord(const Word& w, AxisVector& target) {
    const bool constant = w.expr < 0;
    switch (w.kind) {
        case WordKind::G:
            if (!constant) break;
            if (w.number >= 0 && w.number <= 3) state_.motion = static_cast<int>(w.number);
            if (w.number >= 17 && w.number <= 20) state_.plane = static_cast<int>(w.number);
            if (w.number == 90 || w.number == 91) state_.incremental = w.number == 91;
            break;
        case WordKind::Axis: {
            const int axis = axisIndex(w);
            if (axis < 0) break;
            if (!constant) {
                state_.known[static_cast<std::size_t>(axis)] = false;
            } else {
                target[axis] = state_.incremental ? target[axis] + w.number : w.number;
            }
            break;
        }
        case WordKind::F:
            state_.pathFeed = constant ? w.number : 0.0;
            state_.axisFeedAxis = -1;
            break;
        case WordKind::T:
            if (constant) state_.tool = clampedInteger(w.number, kNoNumber, kLongest);
            break;
        case WordKind::E:
            if (constant) state_.edge = clampedInteger(w.number, kNoNumber, kLongest);
            break;
        default:
            break;
    }
}

int Analyzer::axisIndex(const Word& w) const {
    std::string name(1, w.letter);
    if (w.axisIndex > 0) name += static_cast<char>('0' + w.axisIndex);
    return limits_.indexOf(name);
}

/// A compiler word outside a segment; true when it is ours (removed).
bool Analyzer::compilerWordOutside(std::size_t i, const Program& program, const Word& w) {
    const std::string_view text = program.text(w.text);
    const std::string keyword = keywordIn(text);
    if (keyword == "LA_ON") return startSegment(i);
    if (keyword == "LA_OFF") {
        report(i, "LA_OFF_WITHOUT_ON", "LA_OFF without LA_ON");
        return true;
    }
    if (lookupKeyword(keyword).keywordClass == KeywordClass::AxisFeed) {
        report(i, "LA_AXIS_FEED_OUTSIDE", "F<axis>= only between LA_ON and LA_OFF");
        return true;
    }
    return variableWord(i, keyword, program.text(w.args));
}

// ---------------------------------------------------------------- variables

std::optional<double> Analyzer::rangedValue(std::size_t i, const Range& range,
                                            std::string_view args) {
    const std::string_view value = valueAfterEquals(args);
    if (value.empty()) {
        report(i, "LA_VALUE_MISSING", std::string(range.name) + " needs = value");
        return std::nullopt;
    }
    const CompileTimeValue v = evaluate(i, value);
    if (!v.ok) {
        report(i, "LA_BAD_VALUE", std::string(range.name) + ": " + v.problem);
        return std::nullopt;
    }
    if (v.value < range.min || v.value > range.max ||
        (range.whole && v.value != std::floor(v.value))) {
        report(i, "LA_VALUE_RANGE", std::string(range.name) + " out of range",
               {std::string(range.name) + " = " + formatCoordinate(v.value) + "; allowed " +
                formatCoordinate(range.min) + " .. " + formatCoordinate(range.max) +
                (range.whole ? ", whole numbers" : "")});
        return std::nullopt;
    }
    return v.value;
}

CompileTimeValue Analyzer::evaluate(std::size_t i, std::string_view text) {
    CompileTimeValue v = evaluateCompileTimeValue(text, processIndex_, defaults_.readNcVariable);
    for (const std::string& variable : v.unreadVariables)
        context_.reportAt(blocks_, i, Severity::Warning, "LA_ACD_NO_CONTROLLER",
                          "ACD_COMP: " + variable + " read as 0",
                          {"No controller data at compile time: the NC variable " + variable +
                           " was taken as 0 (its initial value)."});
    return v;
}

/// METB VFBT BBTRC TRC ADTRC ACC_EFF TL_RADIUS; true when ours.
bool Analyzer::variableWord(std::size_t i, const std::string& keyword, std::string_view args) {
    static const Range kRanges[] = {{"METB", 3, 30, false},        {"VFBT", 1, 10, false},
                                    {"BBTRC", 1, 10, true},        {"TRC", 0, 2, true},
                                    {"ADTRC", 0, 99999999, false}, {"ACC_EFF", 1, 200, false}};
    if (keyword == "TL_RADIUS") return toolRadius(i, args), true;
    for (const Range& range : kRanges) {
        if (keyword != range.name) continue;
        const std::optional<double> v = rangedValue(i, range, args);
        if (!v) return true;
        if (keyword == "METB") state_.metbMs = *v;
        if (keyword == "VFBT") state_.vfbt = *v;
        if (keyword == "BBTRC") state_.bbtrc = static_cast<int>(*v);
        if (keyword == "TRC") state_.trc = static_cast<int>(*v);
        if (keyword == "ADTRC") state_.adtrc = *v;
        if (keyword == "ACC_EFF") state_.accEff = *v;
        return true;
    }
    if (keyword == "ACD_COMP" || keyword == "ACD") {
        report(i, "LA_ACD_ALONE", keyword + " only as a value of a variable");
        return true;
    }
    return false;  // another pass's keyword
}

/// TL_RADIUS[T, E] = value; [ ] / missing numbers: the current T / E.
void Analyzer::toolRadius(std::size_t i, std::string_view args) {
    const std::size_t open = args.find('['), close = args.find(']');
    if (open == std::string_view::npos || close == std::string_view::npos || close < open)
        return void(report(i, "LA_TL_RADIUS_SYNTAX", "TL_RADIUS[T no., E no.] = radius"));
    const std::string inside(args.substr(open + 1, close - open - 1));
    const std::size_t comma = inside.find(',');
    long numbers[2] = {state_.tool, state_.edge};
    const std::string parts[2] = {inside.substr(0, comma),
                                  comma == std::string::npos ? "" : inside.substr(comma + 1)};
    for (int k = 0; k < 2; ++k) {
        const std::string text = parts[k];
        if (text.find_first_not_of(' ') == std::string::npos) continue;
        const CompileTimeValue v = evaluate(i, text);
        const std::optional<long> whole = v.ok ? exactInteger<long>(v.value) : std::nullopt;
        if (!whole) return void(report(i, "LA_TL_RADIUS_SYNTAX", "TL_RADIUS: bad T or E number"));
        numbers[k] = *whole;
    }
    if (numbers[0] < 1 || numbers[0] > 9999999 || numbers[1] < 1 || numbers[1] > 9)
        return void(report(i, "LA_VALUE_RANGE", "TL_RADIUS: T 1..9999999, E 1..9"));
    const std::optional<double> r =
        rangedValue(i, {"TL_RADIUS", 0, 999.99999, false}, args.substr(close + 1));
    if (r) state_.radii[{numbers[0], numbers[1]}] = *r;
}

}  // namespace detail

LookAheadAnalysis analyzeLookAhead(const BlockSequence& blocks, CompileContext& context,
                                   const LookAheadDefaults& defaults) {
    return detail::Analyzer(blocks, context, defaults).run();
}

}  // namespace mtc::core::lookahead
