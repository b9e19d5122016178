#include "cnc_core/contour/GneExpansion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "cnc_core/contour/ContourSolver.h"
#include "cnc_core/contour/CycleSupport.h"
#include "cnc_core/contour/GneText.h"
#include "cnc_core/language/CheckedNumber.h"

namespace mtc::core::gne {

std::string BlockWriter::number(double value) {
    double rounded = std::round(value * 1e4) / 1e4;
    if (rounded == 0.0) rounded = 0.0;  // no "-0"
    return formatValue(rounded);
}

std::string BlockWriter::point(const Point& p) const {
    if (plane_ == GnePlane::Turning) return "X" + number(p.y()) + " Z" + number(p.x());
    return "X" + number(p.x()) + " Y" + number(p.y());
}

std::string BlockWriter::feedWord() {
    if (feedWritten_) return "";
    feedWritten_ = true;
    return " F" + number(feed_);
}

void BlockWriter::feed(const Point& p, double f) {
    setFeed(f);
    blocks.push_back("G1 " + point(p) + feedWord());
}

void BlockWriter::segment(const Segment& s) {
    if (!s.isArc()) {
        blocks.push_back("G1 " + point(s.end) + feedWord());
        return;
    }
    const std::string centre = plane_ == GnePlane::Turning
                                   ? " I" + number(s.centre.y()) + " K" + number(s.centre.x())
                                   : " I" + number(s.centre.x()) + " J" + number(s.centre.y());
    blocks.push_back((s.kind == Segment::ArcCW ? "G2 " : "G3 ") + point(s.end) + centre +
                     feedWord());
}

std::vector<Segment> translated(std::vector<Segment> path, const Point& shift) {
    for (Segment& s : path)
        s.start += shift, s.end += shift, s.centre += shift;
    return path;
}

Point edgeVector(int edge) {
    static const Point kVectors[10] = {{0, 0}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1},
                                       {1, 0}, {0, 1}, {-1, 0}, {0, -1},  {0, 0}};
    return edge >= 0 && edge <= 9 ? kVectors[edge] : Point(0, 0);
}

std::string toolBlock(const ToolAssumption& t) {
    std::string text = "T" + std::to_string(t.tool) + " ;GNE TOOL";
    if (t.turning)
        text += " EDGE " + std::to_string(t.edge) + " TR " + formatValue(t.radius) + " CA " +
                formatValue(t.cornerAngle) + " SA " + formatValue(t.settingAngle);
    else
        text += " TR " + formatValue(t.radius);
    return text;
}

bool parseToolBlock(const std::string& text, ToolAssumption& t) {
    std::istringstream in(text);
    std::string tword, marker, name;
    if (!(in >> tword >> marker >> name) || tword.size() < 2 || tword[0] != 'T' ||
        marker != ";GNE" || name != "TOOL")
        return false;
    t = ToolAssumption{};
    char* end = nullptr;
    const long tool = std::strtol(tword.c_str() + 1, &end, 10);  // atoi: undefined on overflow
    if (*end != '\0' || tool < 1 || tool > 9'999'999) return false;
    t.tool = static_cast<int>(tool);
    t.turning = false;
    std::string key;
    double value = 0;
    while (in >> key >> value) {
        if (key == "EDGE") {
            const std::optional<int> edge = exactInteger(value);
            if (!edge || *edge < 0 || *edge > 9) return false;
            t.edge = *edge, t.turning = true;
        } else if (key == "TR")
            t.radius = value;
        else if (key == "CA")
            t.cornerAngle = value;
        else if (key == "SA")
            t.settingAngle = value;
        else
            return false;
    }
    return t.tool > 0;
}

namespace {

class Expander {
  public:
    GneExpansion run(const GneDocument& document) {
        for (const GneItem& item : document.items) {
            if (item.isContour)
                addContour(item.contour);
            else if (item.call.keyword.rfind("WINDOW_", 0) == 0)
                setWindow(item.call);
            else if (item.call.keyword.rfind("FORM_", 0) == 0)
                addForm(item.call);
            else
                expandCycle(item.call);
        }
        return std::move(result_);
    }

  private:
    void error(std::uint32_t line, const char* code, std::string message) {
        result_.diagnostics.push_back({line, code, std::move(message)});
    }

    void addGeometry(Geometry g) {
        for (const Geometry& other : result_.geometries)
            if (other.number == g.number)
                return error(g.line, "GNE_NUMBER_TWICE",
                             "geometry number " + std::to_string(g.number) +
                                 " is already used (line " + std::to_string(other.line) + ")");
        result_.geometries.push_back(std::move(g));
    }

    void addContour(const Contour& contour) {
        ContourSolution solution = solveContour(contour);
        for (const GneDiagnostic& d : solution.diagnostics)
            result_.diagnostics.push_back(d);
        if (!solution.complete()) {
            failed_.push_back(contour.number);  // its cycles add no second error
            return;
        }
        Geometry g;
        g.number = contour.number;
        g.plane = contour.plane;
        g.line = contour.line;
        g.closed = (solution.path.back().end - solution.path.front().start).norm() < 1e-6;
        g.paths.push_back(solution.path);
        if (contour.raw) {  // the blank of the cycles after it (G-007), not machined
            rawContours_.push_back(contour.number);
            if (contour.plane == GnePlane::Turning) rawBlank_ = std::move(g);
            return;
        }
        addGeometry(std::move(g));
    }

    void setWindow(const GneCall& call) {
        const CallSpec& spec = *findCallSpec(call.keyword);
        auto v = [&](std::size_t i) { return paramValue(spec, call, i); };
        stock_.known = true;
        stock_.plane = spec.plane;
        rawBlank_.reset();  // a new window is a new blank
        if (spec.plane == GnePlane::Turning) {
            stock_.low = Point(std::min(v(0), v(1)), v(3));
            stock_.high = Point(std::max(v(0), v(1)), v(2));
            if (v(3) >= v(2)) error(call.line, "GNE_WINDOW", "XMIN must be smaller than XMAX");
        } else {
            stock_.low = Point(std::min(v(0), v(2)), std::min(v(1), v(3)));
            stock_.high = Point(std::max(v(0), v(2)), std::max(v(1), v(3)));
            stock_.top = v(4);
            stock_.bottom = v(5);
        }
    }

    void addForm(const GneCall& call) {
        Geometry g;
        std::string problem;
        if (!formGeometry(call, g, problem))
            return error(call.line, "GNE_FORM", call.keyword + ": " + problem);
        addGeometry(std::move(g));
    }

    const Geometry* geometry(int number) const {
        for (const Geometry& g : result_.geometries)
            if (g.number == number) return &g;
        return nullptr;
    }

    void expandCycle(const GneCall& call);

    GneExpansion result_;
    Stock stock_;
    std::optional<Geometry> rawBlank_;  ///< the last RAW contour since the window
    std::vector<int> rawContours_;
    std::vector<int> failed_;  ///< geometry numbers that did not solve
};

void Expander::expandCycle(const GneCall& call) {
    CycleInput in;
    in.spec = findCallSpec(call.keyword);
    in.call = &call;
    in.stock = stock_;
    if (rawBlank_) in.rawBlank = &*rawBlank_;
    const int number = static_cast<int>(in.value(0));
    in.geometry = geometry(number);
    if (std::find(failed_.begin(), failed_.end(), number) != failed_.end()) return;
    if (!in.geometry) {
        const bool raw =
            std::find(rawContours_.begin(), rawContours_.end(), number) != rawContours_.end();
        return error(call.line, "GNE_NO_GEOMETRY",
                     call.keyword + ": " +
                         (raw ? "contour " + std::to_string(number) +
                                    " is a RAW contour (drawn only, not machined)"
                              : "no solved contour or form number " + std::to_string(number) +
                                    " before it"));
    }
    if (in.geometry->plane != in.spec->plane)
        return error(
            call.line, "GNE_WRONG_PLANE",
            call.keyword + ": geometry " + std::to_string(number) + " lies in the other plane");
    const bool turning = in.spec->plane == GnePlane::Turning;
    ToolAssumption tool;
    tool.tool = static_cast<int>(in.value(1));
    tool.turning = turning;
    tool.line = call.line;
    if (turning) {
        tool.edge = static_cast<int>(in.value(kCycleEdge));
        tool.radius = in.value(kCycleToolRadius);
        tool.cornerAngle = in.value(kCycleCornerAngle);
        tool.settingAngle = in.value(kCycleSettingAngle);
    } else {
        tool.radius = in.value(kMillToolRadius);
    }
    BlockWriter out(in.spec->plane);
    out.raw(turning ? "G90 G18 G40 G15" : "G90 G17 G40");
    out.raw(toolBlock(tool));
    const double speed = in.value(turning ? std::size_t{kCycleSpeed} : std::size_t{kMillSpeed});
    if (speed > 0) out.raw("S" + BlockWriter::number(speed) + " M3");
    std::string problem;
    bool good = false;
    if (call.keyword == "CYCLE_10")
        good = turningContourCut(in, 0.0, out, problem);
    else if (call.keyword == "CYCLE_12")
        good = turningContourCut(in, in.value(kCycleUniformAllowance), out, problem);
    else if (call.keyword == "CYCLE_11")
        good = turningRoughing(in, out, problem);
    else
        good = millingContourCut(in, out, problem);
    if (!good) return error(call.line, "GNE_CYCLE", call.keyword + ": " + problem);
    result_.tools.push_back(tool);
    result_.calls.push_back({call.line, call.keyword, std::move(out.blocks)});
}

}  // namespace

GneExpansion expandGne(const GneDocument& document) {
    return Expander().run(document);
}

}  // namespace mtc::core::gne
