#include "cnc_core/removal/ProgramStock.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "cnc_core/contour/ContourSolver.h"
#include "cnc_core/contour/GneSchema.h"
#include "cnc_core/contour/GneText.h"
#include "cnc_core/interp/MotionPlanner.h"
#include "cnc_core/toolpath/ToolpathBuilder.h"

namespace mtc::core::removal {

namespace {

std::string_view trimmed(std::string_view s) {
    const std::size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string_view::npos) return {};
    return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

/// The instruction of a line: without '/', the N number (with its enhanced
/// number), ':' and the ';' the compiler puts before a GNE instruction
/// (`N0003 ;WINDOW_02 (...)`).
std::string_view instruction(std::string_view line) {
    line = trimmed(line);
    const auto dropComment = [&] {
        if (!line.empty() && line.front() == ';') line = trimmed(line.substr(1));
    };
    dropComment();
    if (!line.empty() && line.front() == '/') line = trimmed(line.substr(1));
    if (line.size() > 1 && (line[0] == 'N' || line[0] == 'n') &&
        std::isdigit(static_cast<unsigned char>(line[1]))) {
        std::size_t i = 1;
        while (i < line.size() &&
               (std::isdigit(static_cast<unsigned char>(line[i])) || line[i] == ':'))
            ++i;
        line = trimmed(line.substr(i));
    }
    if (!line.empty() && line.front() == ':') line = trimmed(line.substr(1));
    dropComment();
    return line;
}

/// `text` begins with `word` in upper or lower case letters.
bool startsCaseless(std::string_view text, std::string_view word) {
    if (text.size() < word.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(text[i])) != word[i]) return false;
    return true;
}

bool isWindowInstruction(std::string_view text) {
    return startsCaseless(text, "WINDOW_");
}

/// Calls visit(line, 1-based number) for each line of `source` until it
/// returns false.
template <typename Visit>
void forEachLine(std::string_view source, Visit visit) {
    std::uint32_t number = 1;
    for (std::size_t start = 0; start < source.size(); ++number) {
        std::size_t end = source.find('\n', start);
        if (end == std::string_view::npos) end = source.size();
        const std::string_view line = source.substr(start, end - start);
        start = end + 1;
        if (!visit(line, number)) return;
    }
}

/// The first line of `source` whose instruction is a WINDOW_ keyword: that
/// instruction (what the GNE reader gets) and its 1-based line.
std::optional<std::pair<std::string, std::uint32_t>> findWindow(std::string_view source) {
    std::optional<std::pair<std::string, std::uint32_t>> found;
    forEachLine(source, [&](std::string_view line, std::uint32_t number) {
        if (line.find('_') == std::string_view::npos) return true;  // the common line, fast
        const std::string_view text = instruction(line);
        if (isWindowInstruction(text)) found = std::pair{std::string(text), number};
        return !found;
    });
    return found;
}

/// `text` begins with the GNE word `word` (not a longer name).
bool startsWithWord(std::string_view text, std::string_view word) {
    if (!startsCaseless(text, word)) return false;
    if (text.size() == word.size()) return true;
    const auto next = static_cast<unsigned char>(text[word.size()]);
    return !std::isalnum(next) && next != '_';
}

/// `line` holds `word` in upper or lower case letters (a cheap test before
/// a line is taken apart: most lines of a long program are plain moves).
bool mentions(std::string_view line, std::string_view word) {
    for (std::size_t at = 0; at + word.size() <= line.size(); ++at) {
        std::size_t i = 0;
        while (i < word.size() && std::toupper(static_cast<unsigned char>(line[at + i])) == word[i])
            ++i;
        if (i == word.size()) return true;
    }
    return false;
}

/// The window on line `windowLine` of `source` and the first RAW contour
/// after it before the next window, as GNE text for readGne(text,
/// windowLine): the window (it sets the contour's plane) and the lines
/// CONT (n, RAW) ... END_CONT as the GNE writes them or as the compiler
/// leaves them (behind ';'), every other line empty so that the lines keep
/// their numbers. The scan ends at that contour's END_CONT.
std::string rawContourText(std::string_view source, std::uint32_t windowLine) {
    std::string text;
    bool inContour = false;
    forEachLine(source, [&](std::string_view line, std::uint32_t number) {
        if (number < windowLine) return true;
        if (number == windowLine) {
            text += instruction(line);
            text += '\n';
            return true;
        }
        const bool candidate = inContour || mentions(line, "CONT") || mentions(line, "WINDOW_");
        const std::string_view gne = candidate ? instruction(line) : std::string_view{};
        if (isWindowInstruction(gne)) return false;
        if (!inContour && startsWithWord(gne, "CONT") &&
            mentions(gne.substr(0, gne.find(';')), "RAW"))
            inContour = true;
        if (inContour) text += gne;
        text += '\n';
        return !(inContour && startsWithWord(gne, "END_CONT"));
    });
    return text;
}

/// Index of the first block starting on or after `line` (blocks.size() if none).
std::uint32_t blockAtOrAfter(const Program& program, std::uint32_t line) {
    std::uint32_t low = 0, high = static_cast<std::uint32_t>(program.blocks.size());
    while (low < high) {
        const std::uint32_t middle = low + (high - low) / 2;
        if (program.blocks[middle].line < line)
            low = middle + 1;
        else
            high = middle;
    }
    return low;
}

/// The modal state when the program reaches block `block` (a check run
/// from its first block); false when it does not get there.
bool stateAtBlock(Interpreter& interpreter, int number, std::uint32_t block,
                  std::uint64_t blockBudget) {
    if (!interpreter.select(number, 0)) return false;
    if (block == 0) return true;
    interpreter.setStopTarget(StopTarget{interpreter.state().program->number, block, 1});
    std::uint64_t blocks = 0;
    while (blocks < blockBudget) {
        const RunResult run = interpreter.run(std::min<std::uint64_t>(blockBudget - blocks, 65536));
        blocks += std::max<std::uint64_t>(run.blocksInterpreted, 1);
        if (run.status == RunStatus::TargetReached) return true;
        if (run.status != RunStatus::Running && run.status != RunStatus::BudgetExceeded &&
            run.status != RunStatus::Stopped)
            return false;
    }
    return false;
}

/// The window's blank in workpiece coordinates: lo / hi per scene axis;
/// false with `problem` when it has no extent.
struct Blank {
    bool turning = false;
    std::array<double, 3> lo{}, hi{};  ///< milling: the box; turning: Z from lo[2] to hi[2]
    double radius = 0.0, bore = 0.0;   ///< turning
};

bool blankOf(const gne::GneCall& call, Blank& blank, std::string& problem) {
    const gne::CallSpec& spec = *gne::findCallSpec(call.keyword);
    const auto v = [&](std::size_t i) { return gne::paramValue(spec, call, i); };
    for (std::size_t i = 0; i < spec.params.size(); ++i)
        if (!std::isfinite(v(i))) return problem = "a value is not a finite number", false;
    blank.turning = spec.plane == gne::GnePlane::Turning;
    if (blank.turning) {  // ZMIN, ZMAX, XMAX [, XMIN]
        blank.lo[2] = std::min(v(0), v(1));
        blank.hi[2] = std::max(v(0), v(1));
        blank.radius = v(2);
        blank.bore = v(3);
        if (blank.lo[2] == blank.hi[2]) return problem = "ZMIN and ZMAX are equal", false;
        if (blank.bore >= blank.radius) return problem = "XMIN must be smaller than XMAX", false;
        return true;
    }
    // XMIN, YMIN, XMAX, YMAX [, ZTOP [, ZBOT]]: corners in either order, as the GNE draws them
    blank.lo = {std::min(v(0), v(2)), std::min(v(1), v(3)), v(5)};
    blank.hi = {std::max(v(0), v(2)), std::max(v(1), v(3)), v(4)};
    if (blank.lo[0] == blank.hi[0]) return problem = "XMIN and XMAX are equal", false;
    if (blank.lo[1] == blank.hi[1]) return problem = "YMIN and YMAX are equal", false;
    if (blank.hi[2] <= blank.lo[2]) return problem = "ZTOP must lie above ZBOT", false;
    return true;
}

/// The closed outline (axial, radius) of a solved turning contour, shifted
/// by `axialOffset`: an open contour is closed along the spindle axis.
std::vector<std::array<double, 2>> blankOutline(const std::vector<gne::Segment>& path,
                                                double axialOffset) {
    std::vector<gne::Point> points = gne::tessellate(path, 0.01);
    if ((points.back() - points.front()).norm() > 1e-6) {
        const gne::Point first = points.front(), last = points.back();
        points.emplace_back(last.x(), 0.0);
        points.emplace_back(first.x(), 0.0);
    } else {
        points.pop_back();
    }
    std::vector<std::array<double, 2>> outline;
    outline.reserve(points.size());
    for (const gne::Point& p : points)  // plane order: 1st axis Z, 2nd axis X
        outline.push_back({p.x() + axialOffset, p.y()});
    return outline;
}

/// A turning window's blank from the first RAW contour of the turning plane
/// after it, up to the next window (TP-021): the stock's outline; an error
/// REMOVAL_RAW_CONTOUR and no stock when that contour does not solve.
void shapeFromRawContour(const Program& program, std::uint32_t windowLine, double axialOffset,
                         ProgramStock& result) {
    const gne::GneDocument read =
        gne::readGne(rawContourText(program.source, windowLine), windowLine);
    for (const gne::GneItem& item : read.items) {
        if (!item.isContour || !item.contour.raw || item.contour.plane != gne::GnePlane::Turning)
            continue;
        const gne::Contour& contour = item.contour;
        StockOrigin& origin = result.origin;
        origin.rawContour = contour.number;
        origin.rawLine = contour.line;
        const gne::ContourSolution solution = gne::solveContour(contour);
        if (!solution.complete()) {
            const std::uint32_t block = blockAtOrAfter(program, contour.line);
            const SourceLocation where{program.number,
                                       block < program.blocks.size() ? program.blockId(block) : "",
                                       static_cast<int>(contour.line), 0};
            const std::string why = solution.diagnostics.empty()
                                        ? std::string("it has no elements")
                                        : solution.diagnostics.front().message;
            result.diagnostics.error("REMOVAL_RAW_CONTOUR", where,
                                     "the RAW contour " + std::to_string(contour.number) +
                                         " cannot be the blank: " + why);
            result.stock = Stock{};  // nothing is cut rather than the wrong blank
            return;
        }
        result.stock.outline = blankOutline(solution.path, axialOffset);
        return;
    }
}

}  // namespace

ProgramStock programStock(const ProcessConfig& config, const ProgramStore& programs, int number,
                          std::shared_ptr<const ZeroOffsetTable> zeroOffsets,
                          std::uint64_t blockBudget) {
    ProgramStock result;
    result.stock = stockOf(config);
    const ProgramPtr program = programs.find(config.index, number);
    if (!program) return result;
    const auto window = findWindow(program->source);
    if (!window) return result;
    StockOrigin& origin = result.origin;
    origin.fromWindow = true;
    origin.where = {program->number, "", static_cast<int>(window->second), 0};
    const std::uint32_t block = blockAtOrAfter(*program, window->second);
    if (block < program->blocks.size()) origin.where.block = program->blockId(block);
    result.stock = Stock{};  // the window's, or none
    const auto refuse = [&](const std::string& why) {
        result.diagnostics.error("REMOVAL_WINDOW", origin.where,
                                 "the drawing window cannot be the stock: " + why);
        return result;
    };
    const gne::GneDocument read = gne::readGne(window->first, window->second);
    if (!read.diagnostics.empty()) return refuse(read.diagnostics.front().message);
    if (read.items.empty() || read.items.front().isContour) return refuse("not a WINDOW_01/02");
    const gne::GneCall& call = read.items.front().call;
    origin.keyword = call.keyword;
    Blank blank;
    std::string problem;
    if (!blankOf(call, blank, problem)) return refuse(call.keyword + ": " + problem);

    NullSink sink;
    InterpreterServices services;
    services.zeroOffsets = std::move(zeroOffsets);
    Interpreter interpreter(config, programs, sink, services);
    interpreter.options().continueAfterError = true;
    if (!stateAtBlock(interpreter, number, block, blockBudget))
        return refuse("the program does not reach it (its zero offset is unknown)");
    const ModalState& modal = interpreter.state().modal;
    origin.zeroOffset = modal.g[kGroupZeroOffset];
    const MotionPlanner planner(&interpreter.axes(), &interpreter.zeroOffsets());
    const ToolpathBuilder scene(interpreter.axes());
    std::array<double, 3> offset{0, 0, 0};
    for (int d = 0; d < 3; ++d)
        if (const int axis = scene.machineAxisOfScene(d); axis >= 0)
            offset[static_cast<std::size_t>(d)] = planner.offsetOf(modal, axis);
    if (blank.turning) {
        result.stock.shape = Stock::Shape::Cylinder;
        result.stock.axis = 2;  // the turning plane's 1st axis, Z (G18)
        result.stock.radius = blank.radius;
        result.stock.from = blank.lo[2] + offset[2];
        result.stock.to = blank.hi[2] + offset[2];
        if (blank.bore > 0.0)
            result.diagnostics.warning("REMOVAL_WINDOW_SIMPLIFIED", origin.where,
                                       "the bore XMIN of the drawing window is not simulated: "
                                       "the stock is a solid bar");
        if (offset[0] != 0.0)
            result.diagnostics.warning("REMOVAL_WINDOW_SIMPLIFIED", origin.where,
                                       "the zero offset shifts X: the bar stays on the spindle "
                                       "axis (X0 of the machine)");
        shapeFromRawContour(*program, window->second, offset[2], result);
        return result;
    }
    result.stock.shape = Stock::Shape::Block;
    for (std::size_t d = 0; d < 3; ++d) {
        result.stock.min[d] = blank.lo[d] + offset[d];
        result.stock.max[d] = blank.hi[d] + offset[d];
    }
    return result;
}

}  // namespace mtc::core::removal
