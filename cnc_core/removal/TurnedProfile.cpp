#include "cnc_core/removal/TurnedProfile.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "cnc_core/removal/HeightField.h"
#include "cnc_core/removal/SweptDisc.h"

namespace mtc::core::removal {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kUnreached = std::numeric_limits<double>::infinity();

/// The radius the swept nose comes closest to the axis at in the slice at
/// `axial` (0 when it crosses the axis; kUnreached when it misses the slice).
double noseReach(const SweptRowScanner& nose, double axial) {
    const Span reach = nose.row(axial);
    if (reach.empty()) return kUnreached;
    if (reach.lo <= 0.0 && reach.hi >= 0.0) return 0.0;
    return std::min(std::fabs(reach.lo), std::fabs(reach.hi));
}

/// The same for the insert behind the nose: from every position whose nose
/// centre lies on the other side of the slice than the insert, the insert
/// takes what lies beyond the nose's inner edge (radius - nose).
double bodyReach(double ua, double ra, double ub, double rb, double nose, int body, double axial) {
    if (body == 0) return kUnreached;
    // Positions t in [0, 1] with body * (axial - u(t)) >= 0, u(t) = ua + t (ub - ua).
    double lo = 0.0, hi = 1.0;
    const double du = ub - ua, gap = axial - ua;
    if (du == 0.0) {
        if (body * gap < 0.0) return kUnreached;
    } else if (body * du > 0.0) {
        hi = std::min(hi, gap / du);
    } else {
        lo = std::max(lo, gap / du);
    }
    if (!(lo <= hi)) return kUnreached;
    return std::min(ra + (rb - ra) * lo, ra + (rb - ra) * hi) - nose;
}

/// A radial tool's flat tip, `half` to either side of its centre along the
/// axis: the lowest tip radius among the positions whose tip spans the slice.
double flatReach(double ua, double ra, double ub, double rb, double half, double axial) {
    // Positions t in [0, 1] with |u(t) - axial| <= half.
    double lo = 0.0, hi = 1.0;
    const double du = ub - ua;
    if (du == 0.0) {
        if (!(std::fabs(ua - axial) <= half)) return kUnreached;
    } else {
        const double t1 = (axial - half - ua) / du, t2 = (axial + half - ua) / du;
        lo = std::max(lo, std::min(t1, t2));
        hi = std::min(hi, std::max(t1, t2));
    }
    if (!(lo <= hi)) return kUnreached;
    const double r1 = ra + (rb - ra) * lo, r2 = ra + (rb - ra) * hi;
    return r1 <= 0.0 && r2 >= 0.0 ? 0.0 : std::min(std::fabs(r1), std::fabs(r2));
}

/// How far towards the axis a tool sweeping from (axial a, radial a) to
/// (axial b, radial b) reaches, slice by slice.
class ToolReach {
  public:
    ToolReach(double ua, double ra, double ub, double rb, const Cutter& tool)
        : ua_(ua),
          ra_(ra),
          ub_(ub),
          rb_(rb),
          nose_(tool.radius),
          body_(tool.radial ? 0 : tool.body),
          radial_(tool.radial),
          scanner_(SweptDisc{ra, ua, rb, ub, tool.radius}) {
        valid_ = std::isfinite(ua) && std::isfinite(ra) && std::isfinite(ub) && std::isfinite(rb) &&
                 nose_ >= 0.0;
    }
    bool valid() const { return valid_; }
    /// The axial range of the slices it can reach: the nose (or flat tip),
    /// and behind a nose on the insert's side all up to the end of the bar.
    double low() const {
        return body_ < 0 ? -std::numeric_limits<double>::infinity() : std::min(ua_, ub_) - nose_;
    }
    double high() const {
        return body_ > 0 ? std::numeric_limits<double>::infinity() : std::max(ua_, ub_) + nose_;
    }
    /// The inner radius it reaches in the slice at `axial` (at least 0;
    /// kUnreached when it misses the slice).
    double at(double axial) const {
        const double reach = radial_ ? flatReach(ua_, ra_, ub_, rb_, nose_, axial)
                                     : std::min(noseReach(scanner_, axial),
                                                bodyReach(ua_, ra_, ub_, rb_, nose_, body_, axial));
        return std::max(0.0, reach);
    }

  private:
    double ua_, ra_, ub_, rb_, nose_;
    int body_;
    bool radial_;
    bool valid_ = false;
    SweptRowScanner scanner_;
};

}  // namespace

TurnedProfile::TurnedProfile(double radius, double from, double to, int slices)
    : radius_(radius),
      from_(from),
      to_(to),
      length_((to - from) / std::max(slices, 1)),
      radii_(static_cast<std::size_t>(std::max(slices, 1)), radius) {}

template <typename Visit>
bool TurnedProfile::forEachReach(double axialA, double radialA, double axialB, double radialB,
                                 const Cutter& tool, Visit visit) const {
    const ToolReach reach(axialA, radialA, axialB, radialB, tool);
    if (!reach.valid()) return false;
    const auto [first, last] = cellsWithin(reach.low(), reach.high(), from_, length_, slices());
    for (int k = first; k <= last; ++k) {
        const double inner = reach.at(sliceCentre(k));
        if (inner != kUnreached && visit(k, inner)) return true;
    }
    return false;
}

bool TurnedProfile::cut(double axialA, double radialA, double axialB, double radialB,
                        const Cutter& tool) {
    // Outside the bar all along (the insert stands further out): nothing to scan.
    if (std::min(radialA, radialB) - tool.radius > radius_) return false;
    bool removed = false;
    forEachReach(axialA, radialA, axialB, radialB, tool, [&](int k, double inner) {
        double& r = radii_[static_cast<std::size_t>(k)];
        if (inner < r) {
            r = inner;
            removed = true;
        }
        return false;
    });
    return removed;
}

bool TurnedProfile::touches(double axialA, double radialA, double axialB, double radialB,
                            const Cutter& tool, double margin) const {
    if (std::min(radialA, radialB) - tool.radius > radius_ + std::max(margin, 0.0)) return false;
    const ToolReach start(axialA, radialA, axialA, radialA, tool);
    return forEachReach(axialA, radialA, axialB, radialB, tool, [&](int k, double inner) {
        const double r = radii_[static_cast<std::size_t>(k)];
        // A slice turned to the axis has nothing left; one the tool meets
        // where it starts is contact only where the move goes deeper.
        if (!(r > 0.0 && inner < r + margin)) return false;
        const double atStart = start.at(sliceCentre(k));
        return !(atStart < r + margin) || inner < atStart - std::fabs(margin);
    });
}

bool TurnedProfile::shapeBlank(const std::vector<std::array<double, 2>>& outline) {
    const std::size_t n = outline.size();
    const auto edge = [&](std::size_t i) {
        const std::array<double, 2>& a = outline[i];
        const std::array<double, 2>& b = outline[(i + 1) % n];
        const bool finite = std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(b[0]) &&
                            std::isfinite(b[1]);
        return finite ? cellsWithin(std::min(a[0], b[0]), std::max(a[0], b[0]), from_, length_,
                                    slices())
                      : std::array<int, 2>{1, 0};
    };
    // An outline that winds to and fro over the bar many times would visit
    // every slice per edge: refused before any work beyond the count.
    std::uint64_t visits = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto [first, last] = edge(i);
        if (first <= last) visits += static_cast<std::uint64_t>(last - first + 1);
    }
    if (visits > kMaxBlankVisits) return false;
    std::vector<double> reach(radii_.size(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::array<double, 2>& a = outline[i];
        const std::array<double, 2>& b = outline[(i + 1) % n];
        const double lo = std::min(a[0], b[0]), hi = std::max(a[0], b[0]);
        const auto [first, last] = edge(i);
        for (int k = first; k <= last; ++k) {
            const double centre = sliceCentre(k);
            if (centre < lo || centre > hi) continue;  // cellsWithin rounds outwards
            const double t = hi > lo ? (centre - a[0]) / (b[0] - a[0]) : 0.0;
            const double r = hi > lo ? a[1] + t * (b[1] - a[1]) : std::max(a[1], b[1]);
            double& kept = reach[static_cast<std::size_t>(k)];
            kept = std::max(kept, std::min(r, radius_));
        }
    }
    radii_ = reach;
    blank_ = std::move(reach);
    return true;
}

double TurnedProfile::removedVolume() const {
    double sum = 0.0;
    for (std::size_t k = 0; k < radii_.size(); ++k) {
        const double before = blank_.empty() ? radius_ : blank_[k];
        sum += before * before - radii_[k] * radii_[k];
    }
    return kPi * sum * length_;
}

double TurnedProfile::blankVolume() const {
    if (blank_.empty()) return kPi * radius_ * radius_ * (to_ - from_);
    double sum = 0.0;
    for (double r : blank_)
        sum += r * r;
    return kPi * sum * length_;
}

}  // namespace mtc::core::removal
