#pragma once

#include <vector>

#include "cnc_core/removal/TurnedProfile.h"

namespace mtc::core::removal {

/// A point of the tool under lateral cylinder surface machining (G32), in
/// the turned part's frame: the angle about the spindle axis (radians, not
/// wrapped: a move over several turns keeps counting), the position along
/// the axis (scene mm) and the radial distance of the end mill's flat face
/// from the axis (mm).
struct JacketPoint {
    double angle = 0.0;
    double axial = 0.0;
    double face = 0.0;
};

/// The turned part's jacket as a radial depth map over the developed
/// surface (D-027): the profile's slices along the axis times `columns`
/// equal angular cells over the whole turn; each cell keeps the outer
/// radius of the material at its centre as the G32 cuts left it (the bar's
/// radius before any). The material at a cell is the smaller of that and
/// the profile's radius of its slice, so turning after milling and milling
/// after turning both stay true. The tool is a driven end mill standing
/// radially: its flat face, a disc of the tool's radius, lies in the plane
/// at distance `face` from the axis, so a cell at angle d beside the tool's
/// centre is cut down to face / cos(d) (a groove along the axis has a flat
/// floor, one around the circumference a round one).
class DevelopedSurface {
  public:
    /// Over `profile`'s slices; columns >= 1 (the caller caps the cells).
    DevelopedSurface(const TurnedProfile& profile, int columns);

    /// Columns for a bar of `radius` at `resolution` (a cell at most
    /// `resolution` wide on the bar's surface), as a double: never overflows.
    static double columnsFor(double radius, double resolution);

    /// Sweeps the end mill of `toolRadius` whose face centre moves straight
    /// from `a` to `b` (straight in angle, axial position and face radius:
    /// a G32 line is a helix, one chord). Work: the cells the sweep covers,
    /// at most every cell of the rows it reaches, whatever the coordinates.
    /// Non-finite points cut nothing. True when material below `profile`'s
    /// surface was removed.
    bool cut(const JacketPoint& a, const JacketPoint& b, double toolRadius,
             const TurnedProfile& profile);

    /// Would the same sweep reach material, without changing anything?
    /// True when at some cell that still has material (the smaller of its
    /// radius and `profile`'s above 0) the face would come below that radius
    /// + `margin` (negative: more than -margin would be cut; positive: the
    /// face comes within `margin` of the surface). A cell the tool meets so
    /// where the sweep starts counts only where the sweep goes more than
    /// |margin| deeper (moving away is no new contact). As
    /// TurnedProfile::touches for the restart's way back (D-021). Work as cut().
    bool touches(const JacketPoint& a, const JacketPoint& b, double toolRadius, double margin,
                 const TurnedProfile& profile) const;

    /// Material the G32 cuts took away below `profile`'s surface (mm^3).
    double removedVolume(const TurnedProfile& profile) const;

    int columns() const { return columns_; }
    int rows() const { return rows_; }
    /// Angle (radians, 0 .. 2 pi) of the centre of column `i`.
    double columnAngle(int i) const { return (i + 0.5) * angleStep_; }
    /// Axial position of the centre of row `j` (the profile's slice j).
    double rowAxial(int j) const { return from_ + (j + 0.5) * sliceLength_; }
    /// Outer radius the G32 cuts left at cell (i, j) (row j: profile slice j).
    double radius(int i, int j) const { return radii_[index(i, j)]; }

  private:
    struct Sweep;
    std::size_t index(int i, int j) const {
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(columns_) +
               static_cast<std::size_t>(i);
    }
    /// Calls visit(i, j, angle, face, sweep) for every cell the sweep from
    /// `a` to `b` covers, with the lowest face over it and the cell's angle
    /// in the sweep's turn (NaN in a row swept over a whole turn), until
    /// visit returns true (then true). Rows whose profile radius + `reach`
    /// lies above the deepest face are skipped.
    template <typename Visit>
    bool forEachCovered(const JacketPoint& a, const JacketPoint& b, double toolRadius,
                        const TurnedProfile& profile, double reach, Visit visit) const;
    template <typename Visit>
    bool visitRow(int j, const Sweep& sweep, Visit& visit) const;

    int columns_;
    int rows_;
    double angleStep_;
    double from_;
    double sliceLength_;
    double barRadius_;
    std::vector<float> radii_;
};

}  // namespace mtc::core::removal
