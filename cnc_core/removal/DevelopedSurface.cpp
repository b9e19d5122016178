#include "cnc_core/removal/DevelopedSurface.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/removal/HeightField.h"
#include "cnc_core/removal/SweptDisc.h"
#include "cnc_core/toolpath/CurveMath.h"

namespace mtc::core::removal {

namespace {

constexpr double kTurn = 2.0 * curve::kPi;
/// Smallest scale (mm per radian) of the developed plane a tool is laid on:
/// a face on or beyond the axis with a tool of radius 0.
constexpr double kMinScale = 1e-3;
/// A cell beside the tool's centre is at most the tool's radius away on a
/// plane of at least that scale, so at most 1 radian; bounded again here so
/// face / cos(offset) stays finite whatever rounding does.
constexpr double kMaxOffset = 1.2;

bool finitePoint(const JacketPoint& p) {
    return std::isfinite(p.angle) && std::isfinite(p.axial) && std::isfinite(p.face);
}

}  // namespace

/// One chord as the rows are scanned: the angles moved by whole turns so the
/// start lies in [0, 2 pi), and the tool's disc laid on the developed plane
/// at `scale` mm per radian: the face radius (where the floor's width is the
/// tool's), at least the tool's radius.
struct DevelopedSurface::Sweep {
    Sweep(const JacketPoint& from, const JacketPoint& to, double toolRadius)
        : a(from),
          b(to),
          scale(std::max({std::min(from.face, to.face), toolRadius, kMinScale})),
          disc{scale * from.angle, from.axial, scale * to.angle, to.axial, toolRadius},
          scanner(disc) {}

    /// The lowest the face comes over a cell at (unwrapped) `angle` while the
    /// disc covers it, at positions `t` of the chord: face / cos(angle
    /// between the cell and the tool's centre), at the ends of the covering
    /// and where the centre passes the cell's angle.
    double lowestFace(double angle, const Span& t) const {
        const auto offsetAt = [&](double u) { return angle - (a.angle + (b.angle - a.angle) * u); };
        const auto floorAt = [&](double u, double offset) {
            const double face = std::max(a.face + (b.face - a.face) * u, 0.0);
            return face / std::cos(std::min(std::fabs(offset), kMaxOffset));
        };
        const double first = offsetAt(t.lo), last = offsetAt(t.hi);
        const bool passes = (first > 0.0) != (last > 0.0);  // the centre passes the cell
        if (a.face == b.face) {  // level (the common case): one cosine at most
            if (passes) return std::max(a.face, 0.0);
            return floorAt(t.lo, std::min(std::fabs(first), std::fabs(last)));
        }
        double lowest = std::min(floorAt(t.lo, first), floorAt(t.hi, last));
        const double sweep = b.angle - a.angle;
        if (passes && sweep != 0.0) {
            const double u = (angle - a.angle) / sweep;
            lowest = std::min(lowest, floorAt(u, 0.0));
        }
        return lowest;
    }

    JacketPoint a, b;
    double scale;
    SweptDisc disc;
    SweptRowScanner scanner;
};

DevelopedSurface::DevelopedSurface(const TurnedProfile& profile, int columns)
    : columns_(std::max(columns, 1)),
      rows_(profile.slices()),
      angleStep_(kTurn / columns_),
      from_(profile.from()),
      sliceLength_(profile.sliceLength()),
      barRadius_(profile.stockRadius()),
      radii_(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_),
             static_cast<float>(profile.stockRadius())) {}

double DevelopedSurface::columnsFor(double radius, double resolution) {
    return std::max(1.0, std::ceil(kTurn * radius / resolution - 1e-9));
}

template <typename Visit>
bool DevelopedSurface::forEachCovered(const JacketPoint& from, const JacketPoint& to,
                                      double toolRadius, const TurnedProfile& profile, double reach,
                                      Visit visit) const {
    if (!finitePoint(from) || !finitePoint(to) || !std::isfinite(toolRadius) ||
        !(toolRadius >= 0.0) || profile.slices() != rows_)
        return false;
    const double deepest = std::min(from.face, to.face);
    if (!(deepest < barRadius_ + reach)) return false;  // above the bar
    const auto [first, last] =
        cellsWithin(std::min(from.axial, to.axial) - toolRadius,
                    std::max(from.axial, to.axial) + toolRadius, from_, sliceLength_, rows_);
    // Whole turns off the start (fmod is exact): the cells' angles are small.
    JacketPoint a = from, b = to;
    a.angle = std::fmod(from.angle, kTurn);
    if (a.angle < 0.0) a.angle += kTurn;
    b.angle = a.angle + (to.angle - from.angle);
    const Sweep sweep(a, b, toolRadius);
    for (int j = first; j <= last; ++j) {
        if (!(deepest < profile.radiusAt(j) + reach)) continue;  // nothing below the face
        if (visitRow(j, sweep, visit)) return true;
    }
    return false;
}

template <typename Visit>
bool DevelopedSurface::visitRow(int j, const Sweep& sweep, Visit& visit) const {
    const Span row = sweep.scanner.row(rowAxial(j));
    if (row.empty()) return false;
    const double lo = row.lo / sweep.scale, hi = row.hi / sweep.scale;  // angles
    if (!(hi - lo < kTurn)) {
        // A full turn and more in this row: every column, at the deepest face
        // (no angle: the sweep meets each column at many).
        const double face = std::max(std::min(sweep.a.face, sweep.b.face), 0.0);
        for (int i = 0; i < columns_; ++i)
            if (visit(i, j, std::nan(""), face, sweep)) return true;
        return false;
    }
    // At most two windows of columns: this turn and the next.
    const double turn = kTurn * std::floor(lo / kTurn);
    for (const double shift : {turn, turn + kTurn}) {
        const auto [first, last] = cellsWithin(lo - shift, hi - shift, 0.0, angleStep_, columns_);
        for (int i = first; i <= last; ++i) {
            const double angle = columnAngle(i) + shift;  // in the sweep's turn
            const Span t = coveringPositions(sweep.disc, sweep.scale * angle, rowAxial(j));
            if (!t.empty() && visit(i, j, angle, sweep.lowestFace(angle, t), sweep)) return true;
        }
    }
    return false;
}

bool DevelopedSurface::cut(const JacketPoint& from, const JacketPoint& to, double toolRadius,
                           const TurnedProfile& profile) {
    bool removed = false;
    forEachCovered(from, to, toolRadius, profile, 0.0,
                   [&](int i, int j, double, double face, const Sweep&) {
                       float& cell = radii_[index(i, j)];
                       if (!(face < cell)) return false;
                       const double before = std::min<double>(cell, profile.radiusAt(j));
                       cell = static_cast<float>(face);
                       removed = cell < before || removed;
                       return false;
                   });
    return removed;
}

bool DevelopedSurface::touches(const JacketPoint& from, const JacketPoint& to, double toolRadius,
                               double margin, const TurnedProfile& profile) const {
    const auto contact = [&](int i, int j, double angle, double face, const Sweep& sweep) {
        const double material = std::min<double>(radius(i, j), profile.radiusAt(j));
        if (!(material > 0.0) || !(face < material + margin)) return false;
        // Met already where the sweep starts: contact only deeper than there
        // (a row swept over whole turns has no angle: never "at the start").
        const double offset = angle - sweep.a.angle;
        const double across = sweep.scale * offset, along = rowAxial(j) - sweep.a.axial;
        const bool covered = across * across + along * along <= toolRadius * toolRadius;
        const double startFace =
            std::max(sweep.a.face, 0.0) / std::cos(std::min(std::fabs(offset), kMaxOffset));
        const bool atStart = covered && startFace < material + margin;
        return !atStart || face < startFace - std::fabs(margin);
    };
    return forEachCovered(from, to, toolRadius, profile, std::max(margin, 0.0), contact);
}

double DevelopedSurface::removedVolume(const TurnedProfile& profile) const {
    if (profile.slices() != rows_) return 0.0;
    double sum = 0.0;
    for (int j = 0; j < rows_; ++j) {
        const double outer = profile.radiusAt(j);
        const float* row = radii_.data() + static_cast<std::size_t>(j) * columns_;
        for (int i = 0; i < columns_; ++i) {
            const double r = row[i];
            if (r < outer) sum += outer * outer - r * r;
        }
    }
    return 0.5 * sum * angleStep_ * sliceLength_;
}

}  // namespace mtc::core::removal
