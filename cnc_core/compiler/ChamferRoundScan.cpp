#include "cnc_core/compiler/ChamferRoundScan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "cnc_core/geometry/ArcSweep.h"
#include "cnc_core/language/CheckedNumber.h"
#include "cnc_core/text/Decimal.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {

namespace {

/// Functions that may not be selected or deselected between the two motion
/// blocks of a chamfer or rounding (seed 001, ch. 2 "Illegal commands").
const char* illegalG(int g) {
    if (g == 15 || g == 16) return "radius/diameter programming";
    if (g >= 17 && g <= 20) return "a change of plane";
    if (g >= 30 && g <= 32) return "a transformation";
    if (g >= 50 && g <= 59) return "a zero offset";
    if (g == 70 || g == 71) return "inch/mm";
    if (g == 72 || g == 73) return "the mirror function";
    if (g == 74) return "homing";
    if (g == 75 || g == 76) return "travel to dead stop";
    if (g == 77) return "repositioning";
    if (g == 78 || g == 79) return "scaling";
    if (g == 90 || g == 91) return "absolute/incremental dimension";
    return nullptr;
}

/// Name of the axis with base definition `definition` ("X", "Y", "Z").
std::string baseAxisName(const ProcessConfig* process, const char* definition) {
    if (process)
        for (const AxisConfig& axis : process->axes)
            if (!axis.definitions.empty() && axis.definitions.front() == definition)
                return axis.name;
    return definition;
}

CompilerPlane standardPlane(int code, const ProcessConfig* process) {
    CompilerPlane plane;
    plane.code = code;
    const std::string x = baseAxisName(process, "X"), y = baseAxisName(process, "Y"),
                      z = baseAxisName(process, "Z");
    if (code == 18) {
        plane.axis[0] = z, plane.axis[1] = x, plane.centre[0] = 'K', plane.centre[1] = 'I';
    } else if (code == 19) {
        plane.axis[0] = y, plane.axis[1] = z, plane.centre[0] = 'J', plane.centre[1] = 'K';
    } else {
        plane.code = 17;
        plane.axis[0] = x, plane.axis[1] = y, plane.centre[0] = 'I', plane.centre[1] = 'J';
    }
    return plane;
}

/// End of the value of a word starting at `begin` ("X12.5", "X = -3", "Z1=4").
std::size_t wordEnd(const std::string& text, std::size_t begin) {
    std::size_t i = begin + 1;
    if (i + 1 < text.size() && text[i] >= '1' && text[i] <= '3' &&
        (text[i + 1] == '=' || text[i + 1] == ' '))
        ++i;
    while (i < text.size() && text[i] == ' ')
        ++i;
    if (i < text.size() && text[i] == '=') ++i;
    while (i < text.size() && text[i] == ' ')
        ++i;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    const char* const data = text.data();  // the digits: the common and the long part
    const std::size_t size = text.size();
    while (i < size && (static_cast<unsigned char>(data[i] - '0') <= 9 || data[i] == '.'))
        ++i;
    return i;
}

/// readNumberPrefix for "12", "1.5", ".8" (at most 15 digits) followed by
/// the end or a blank: the value is digits / 10^decimals, both exact as
/// doubles, so the division rounds as from_chars does. Returns nullptr for
/// any other text.
const char* plainDecimal(const char* first, const char* last, double& value) {
    std::int64_t digits = 0;
    int count = 0, decimals = -1;
    const char* p = first;
    for (; p != last; ++p) {
        if (*p >= '0' && *p <= '9') {
            digits = digits * 10 + (*p - '0');
            ++count;
            if (decimals >= 0) ++decimals;
        } else if (*p == '.' && decimals < 0) {
            decimals = 0;
        } else {
            break;
        }
    }
    if (count == 0 || count > 15 || (p != last && *p != ' ')) return nullptr;
    value = exactDecimal(digits, static_cast<unsigned>(decimals < 0 ? 0 : decimals));
    return p;
}

/// CF/RD value from its raw arguments ("2", "=2.5", " = 1"), read in place.
bool cornerValue(std::string_view args, double& value) {
    std::size_t i = 0;
    while (i < args.size() && args[i] == ' ')
        ++i;
    if (i < args.size() && args[i] == '=') ++i;
    while (i < args.size() && args[i] == ' ')
        ++i;
    if (i >= args.size()) return false;
    const char* stop = args.data() + args.size();
    const char* end = plainDecimal(args.data() + i, stop, value);
    if (!end) end = readNumberPrefix(args.data() + i, stop, value);
    while (end < stop && *end == ' ')
        ++end;
    return (end == stop || *end == '\0') && std::isfinite(value);
}

struct AxisPosition {
    std::string name;
    double value = 0.0;  // geometric units
    bool known = false;
};

/// Modal state carried from block to block.
struct ScanState {
    int motionG = 0;
    bool absolute = true;
    bool diameter = false;
    CompilerPlane plane;
    bool planeChanged = true;  ///< plane differs from the last entry of ScanResult::planes
    std::vector<AxisPosition> positions;

    /// Indices of the positions of plane.axis[0] and [1] (planeIndexValid).
    std::size_t planeIndex[2] = {0, 0};
    bool planeIndexValid = false;

    AxisPosition& position(const std::string& name) {
        for (AxisPosition& p : positions)
            if (sameAxisName(p.name, name)) return p;
        positions.push_back({name, 0.0, false});
        return positions.back();
    }
    /// position(plane.axis[k]); the two are looked up (and made, in this
    /// order) once per plane.
    AxisPosition& planePosition(int k) {
        if (!planeIndexValid) {
            for (int a = 0; a < 2; ++a)
                planeIndex[a] = static_cast<std::size_t>(&position(plane.axis[a]) - &positions[0]);
            planeIndexValid = true;
        }
        return positions[planeIndex[k]];
    }
    /// The plane changed (its axes are looked up again).
    void newPlane() {
        planeChanged = true;
        planeIndexValid = false;
    }
};

std::string wordName(const NumberWord& word) {
    std::string name(1, word.letter);
    if (word.axisIndex > 0) name += static_cast<char>('0' + word.axisIndex);
    return name;
}

void setIllegal(ScannedBlock& out, const char* why, bool isG, int g) {
    if (out.illegal) return;
    out.illegal = why;
    out.illegalIsG = isG;
    out.illegalG = g;
}

/// The words readWords takes whole: a jump ends the corner chain, a CF or
/// RD command gives the block's corner.
void readOtherWord(const Program& program, const Word& word, std::size_t prefixSize,
                   ScannedBlock& out) {
    const std::size_t begin = word.column > prefixSize ? word.column - 1 - prefixSize : 0;
    switch (word.kind) {
        case WordKind::Jump:
            setIllegal(out, "a jump instruction", false, 0);
            break;
        case WordKind::Command: {
            const std::string_view raw = program.text(word.text);
            if (raw.substr(0, 3) == "BRJ" &&
                (raw.size() == 3 || !isalnum(static_cast<unsigned char>(raw[3]))))
                setIllegal(out, "a jump instruction (BRJ)", false, 0);
            if (raw.size() >= 2 && (raw.substr(0, 2) == "CF" || raw.substr(0, 2) == "RD") &&
                (raw.size() == 2 || !isalpha(static_cast<unsigned char>(raw[2])) ||
                 raw[2] == '=')) {
                ++out.cornerCount;
                out.kind = raw[0] == 'C' ? CornerKind::Chamfer : CornerKind::Rounding;
                out.cornerBegin = begin;
                out.cornerEnd = begin + raw.size();
                if (!cornerValue(program.text(word.args), out.size))
                    out.sizeProblem = "the value must be a number (no variable)";
                else if (out.size < 0.0)
                    out.sizeProblem = "the value must not be negative";
                else if (out.size > kMaxCornerSize)
                    out.sizeProblem = "the value must be at most 99999.9999 mm";
            }
            break;
        }
        default:
            break;
    }
}

/// Reads the words of one parsed block into `out` (its axis and centre
/// words into the pools of `result`), updating the G state.
void readWords(const Program& program, const Block& block, std::size_t prefixSize,
               const std::string& text, ScanState& state, ScannedBlock& out, ScanResult& result,
               const CompilerOptions& options) {
    out.axes.begin = out.axes.end = static_cast<std::uint32_t>(result.axisWords.size());
    out.centres.begin = out.centres.end = static_cast<std::uint32_t>(result.centreWords.size());
    bool g20 = false;
    for (std::uint32_t w = block.firstWord; w < block.firstWord + block.wordCount; ++w) {
        // Number words (G, axes, centres: nearly all) without building a Word.
        NumberWord word;
        if (!program.words.readNumber(w, word)) {
            const Word whole = program.words[w];
            if (whole.kind == WordKind::Jump || whole.kind == WordKind::Command) {
                readOtherWord(program, whole, prefixSize, out);
                continue;
            }
            word = numberWordOf(whole);
        }
        const std::size_t begin = word.column > prefixSize ? word.column - 1 - prefixSize : 0;
        switch (word.kind) {
            case WordKind::G: {
                const std::optional<int> number =
                    word.expr < 0 ? exactInteger(word.number) : std::optional<int>(-1);
                if (!number)
                    break;  // G8888888888, G1.5: no G function (the interpreter refuses it)
                const int g = *number;
                if (g >= 0 && g <= 3) {
                    state.motionG = g;
                    out.explicitMotionG = true;
                }
                if (g == 90 || g == 91) state.absolute = g == 90;
                if (g == 15 || g == 16) state.diameter = g == 16;
                if (g >= 17 && g <= 19) {
                    state.plane = standardPlane(g, options.process);
                    state.newPlane();
                }
                if (g == 20) g20 = true;
                if (const char* why = g < 0 ? "a computed G function" : illegalG(g))
                    setIllegal(out, why, true, g);
                break;
            }
            case WordKind::Axis:
            case WordKind::CircleCenter: {
                const bool axis = word.kind == WordKind::Axis;
                (axis ? result.axisWords : result.centreWords)
                    .push_back(
                        {wordName(word), word.number, word.expr >= 0, begin, wordEnd(text, begin)});
                ++(axis ? out.axes : out.centres).end;
                break;
            }
            default:
                break;
        }
    }
    if (!block.label.empty()) setIllegal(out, "a jump label", false, 0);
    if (g20) {  // G20 a b [c]: the words name the plane axes, nothing moves
        if (out.axes.size() >= 2) {
            state.plane.code = 20;
            state.plane.axis[0] = result.axisWords[out.axes.begin].name;
            state.plane.axis[1] = result.axisWords[out.axes.begin + 1].name;
            state.plane.centre[0] = 'I';
            state.plane.centre[1] = 'J';
            state.newPlane();
        }
        result.axisWords.resize(out.axes.begin);
        out.axes.end = out.axes.begin;
    }
}

/// Builds the plane element of a motion block and advances the positions.
void buildMotion(ScanState& state, ScannedBlock& out, const ScanResult& result) {
    const CompilerPlane& plane = state.plane;
    Point2 start, end, centre;
    out.startKnown = true;
    for (int k = 0; k < 2; ++k) {
        AxisPosition& p = state.planePosition(k);
        out.startKnown = out.startKnown && p.known;
        start[k] = p.value;
    }
    end = start;
    centre = start;
    for (std::uint32_t a = out.axes.begin; a < out.axes.end; ++a) {
        const ScannedWord& w = result.axisWords[a];
        const int k = sameAxisName(w.name, plane.axis[0])   ? 0
                      : sameAxisName(w.name, plane.axis[1]) ? 1
                                                            : -1;
        if (k < 0) out.outOfPlane = true;
        if (k >= 0 && w.variable) out.planeVariable = true;
        const double v = w.value * axisScale(w.name, state.diameter);
        if (k >= 0) end[k] = state.absolute ? v : start[k] + v;
        AxisPosition& p = k >= 0 ? state.planePosition(k) : state.position(w.name);
        p.known = !w.variable && (state.absolute || p.known);
        p.value = state.absolute ? v : p.value + v;
    }
    for (std::uint32_t c = out.centres.begin; c < out.centres.end; ++c) {
        const ScannedWord& w = result.centreWords[c];
        const int k = w.name[0] == plane.centre[0] ? 0 : w.name[0] == plane.centre[1] ? 1 : -1;
        if (k < 0) continue;  // the interpreter reports a centre outside the plane
        if (w.variable) out.planeVariable = true;
        const double v = w.value * axisScale(plane.axis[k], state.diameter);
        centre[k] = state.absolute ? v : start[k] + v;
    }
    const double largest = std::max(
        {start.cwiseAbs().maxCoeff(), end.cwiseAbs().maxCoeff(), centre.cwiseAbs().maxCoeff()});
    if (!(largest <= kMaxCornerCoordinate)) {  // also NaN
        out.elementProblem = "a coordinate lies beyond +-1e9 mm";
        out.validElement = false;
        return;
    }
    if (out.motionG == 2 || out.motionG == 3) {
        out.element = PathElement::circle(start, end, centre, out.motionG == 3);
        out.element.fullCircle = closesCircle(start.x(), start.y(), end.x(), end.y());
        const double r1 = (start - centre).norm(), r2 = (end - centre).norm();
        if (r1 < 1e-9)
            out.elementProblem = "the circle's start point is its centre";
        else if (std::fabs(r1 - r2) > 0.002)
            out.elementProblem = "start and end point are not on one circle";
    } else {
        out.element = PathElement::line(start, end);
        if (out.element.length() < 1e-9)
            out.elementProblem = "the block does not move in the plane";
    }
    out.validElement = out.elementProblem == nullptr;
}

}  // namespace

std::string describeIllegal(const ScannedBlock& block) {
    if (!block.illegal) return std::string();
    if (!block.illegalIsG) return block.illegal;
    return block.illegal + std::string(" (G") +
           (block.illegalG < 0 ? "=" : std::to_string(block.illegalG)) + ")";
}

ScanResult scanBlocks(const BlockSequence& blocks, const ParsedSequence& parsed,
                      const CompilerOptions& options) {
    ScanResult result;
    result.blocks.resize(blocks.size());
    result.axisWords.reserve(blocks.size() * 2);
    std::vector<ScannedBlock>& out = result.blocks;
    ScanState state;
    state.plane =
        standardPlane(options.process ? options.process->defaultPlane() : 17, options.process);
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        ScannedBlock& s = out[i];
        const std::int32_t p = parsed.parsedOf[i];
        if (p >= 0) {
            const Block block = parsed.program.blocks[static_cast<std::size_t>(p)];
            readWords(parsed.program, block, blocks[i].prefix.size(), blocks[i].text, state, s,
                      result, options);
        }
        s.motionG = state.motionG;
        s.absolute = state.absolute;
        s.diameter = state.diameter;
        if (state.planeChanged) {  // blocks share their plane until it changes
            result.planes.push_back(state.plane);
            state.planeChanged = false;
        }
        s.plane = static_cast<std::uint32_t>(result.planes.size() - 1);
        s.motion = !s.axes.empty();
        if (s.motion) buildMotion(state, s, result);
    }
    return result;
}

}  // namespace mtc::core
