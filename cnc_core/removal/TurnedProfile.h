#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace mtc::core::removal {

/// Most slice visits TurnedProfile::shapeBlank() makes (tens of ms).
inline constexpr std::uint64_t kMaxBlankVisits = 20'000'000;

/// The tool as the part models cut with it. The mill uses `radius` (a flat
/// end mill along Z). On the lathe, in the plane through the axis: a
/// turning tool's nose of `radius` with its insert on the `body` side
/// (TurnedProfile::cut), or a `radial` tool (a driven end mill or drill
/// standing radially, no cutting edge orientation): a flat end at the tip,
/// `radius` to either side along the axis.
struct Cutter {
    double radius = 0.0;
    int body = 0;
    bool radial = false;
};

/// The lathe's part as a revolved profile: the bar (radius R from `from` to
/// `to` along the spindle axis) cut into slices; each slice keeps the outer
/// radius of the material at its centre. The tool is its nose, a disc in
/// the plane through the axis (axial, radial), and an outside tool: where the
/// swept nose reaches a slice, the material beyond the nose's inner edge is
/// gone (the insert and holder stand outside it). Bores, and material left
/// ahead of a face cut deeper than the nose, are not represented (D-020).
class TurnedProfile {
  public:
    /// slices >= 1; radius > 0, from < to.
    TurnedProfile(double radius, double from, double to, int slices);

    /// Sweeps the tool whose nose centre (a radial tool: the centre of its
    /// tip) moves on the straight line from (axial a, radial a) to (axial b,
    /// radial b). The radial coordinate is signed (a tool beyond the axis).
    /// `tool.body` is the axial side the insert stands on (+1: towards
    /// +axial, the tool points to -axial; -1 the other way; 0: only radially
    /// outside, a grooving tool). Work: the slices the sweep covers, at most
    /// every slice. Chords with a non-finite coordinate cut nothing. True
    /// when material was removed.
    bool cut(double axialA, double radialA, double axialB, double radialB, const Cutter& tool);

    /// Would the same sweep reach material, without changing anything? True
    /// when in some slice that still has material (radius above 0) the tool
    /// would reach below radius + `margin` (negative: more than -margin would
    /// be turned away; positive: the tool comes within `margin` of the
    /// surface, a touch); a slice it meets so where the sweep starts counts
    /// only where the sweep reaches more than |margin| deeper (a move away
    /// from the material is no new contact). Work as cut().
    bool touches(double axialA, double radialA, double axialB, double radialB, const Cutter& tool,
                 double margin) const;

    /// Makes the blank the material inside `outline` (Stock::outline: a
    /// closed polygon of (axial, radius) points): each slice keeps the
    /// outline's largest radius at its centre, at most the bar's radius, 0
    /// where the outline does not reach. Work: the slices each edge spans;
    /// false (nothing changed) when they add up to more than kMaxBlankVisits.
    bool shapeBlank(const std::vector<std::array<double, 2>>& outline);

    /// Material turned away so far (mm^3).
    double removedVolume() const;
    /// The blank's volume (mm^3): the bar's, or less after shapeBlank().
    double blankVolume() const;

    double stockRadius() const { return radius_; }
    double from() const { return from_; }
    double to() const { return to_; }
    int slices() const { return static_cast<int>(radii_.size()); }
    double sliceLength() const { return length_; }
    /// Axial position of the centre of slice `k`.
    double sliceCentre(int k) const { return from_ + (k + 0.5) * length_; }
    /// Outer radius of the material in slice `k` (0: nothing left).
    double radiusAt(int k) const { return radii_[static_cast<std::size_t>(k)]; }

  private:
    /// Calls visit(slice, inner radius the tool reaches there) for every
    /// slice the sweep reaches, in order, until visit returns true (then
    /// true). Nothing for a non-finite coordinate or a sweep outside the bar.
    template <typename Visit>
    bool forEachReach(double axialA, double radialA, double axialB, double radialB,
                      const Cutter& tool, Visit visit) const;

    double radius_;
    double from_;
    double to_;
    double length_;
    std::vector<double> radii_;
    std::vector<double> blank_;  ///< the radii before any cut (empty: all radius_)
};

}  // namespace mtc::core::removal
