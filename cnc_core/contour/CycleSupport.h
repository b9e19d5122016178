#pragma once

// Internal helpers of the cycle expansion: NC block text of segments and
// the data a cycle works on.

#include <string>
#include <vector>

#include "cnc_core/contour/GneExpansion.h"
#include "cnc_core/contour/GneSchema.h"

namespace mtc::core::gne {

/// The blank of the current drawing window.
struct Stock {
    bool known = false;
    GnePlane plane = GnePlane::Turning;
    Point low = Point::Zero();       ///< turning (ZMIN, XMIN); milling (XMIN, YMIN)
    Point high = Point::Zero();      ///< turning (ZMAX, XMAX); milling (XMAX, YMAX)
    double top = 0.0, bottom = 0.0;  ///< milling Z
};

/// Writes NC block texts in one plane.
class BlockWriter {
  public:
    explicit BlockWriter(GnePlane plane) : plane_(plane) {}
    /// A coordinate rounded to 0.0001 mm.
    static std::string number(double value);
    /// "X<p.y> Z<p.x>" (turning) or "X<p.x> Y<p.y>" (milling).
    std::string point(const Point& p) const;
    void rapid(const Point& p) { blocks.push_back("G0 " + point(p)); }
    void feed(const Point& p, double f);
    /// One G1/G2/G3 block; F only on the first cutting block after `setFeed`.
    void segment(const Segment& s);
    void setFeed(double f) { feed_ = f, feedWritten_ = false; }
    void raw(std::string text) { blocks.push_back(std::move(text)); }
    std::vector<std::string> blocks;

  private:
    std::string feedWord();
    GnePlane plane_;
    double feed_ = 0.0;
    bool feedWritten_ = true;
};

/// Cycle input shared by the turning and milling cycles.
struct CycleInput {
    const CallSpec* spec = nullptr;
    const GneCall* call = nullptr;
    const Geometry* geometry = nullptr;
    Stock stock;
    /// The RAW contour (initial part contour) that is the blank, nullptr =
    /// the window's rectangle is the blank (G-007).
    const Geometry* rawBlank = nullptr;
    double value(std::size_t i) const { return paramValue(*spec, *call, i); }
};

/// CYCLE_10 / CYCLE_12: the contour (plus a uniform allowance) once.
bool turningContourCut(const CycleInput& in, double allowance, BlockWriter& out,
                       std::string& problem);
/// Most passes a roughing cycle may write: more cannot stand in a program
/// of at most 10,000 lines (4 blocks a pass), and the count must not grow
/// with the blank's size over the depth of cut (issue 15 §1).
constexpr int kMaxRoughingPasses = 2000;

/// CYCLE_11: parallel longitudinal roughing passes.
bool turningRoughing(const CycleInput& in, BlockWriter& out, std::string& problem);
/// CYCLE_40: contour cut milling with tool radius compensation.
bool millingContourCut(const CycleInput& in, BlockWriter& out, std::string& problem);

/// Translates every segment by `shift`.
std::vector<Segment> translated(std::vector<Segment> path, const Point& shift);

}  // namespace mtc::core::gne
