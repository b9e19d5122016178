#include "cnc_core/removal/TurnedProfile.h"

#include <algorithm>
#include <cmath>
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

}  // namespace

TurnedProfile::TurnedProfile(double radius, double from, double to, int slices)
    : radius_(radius),
      from_(from),
      to_(to),
      length_((to - from) / std::max(slices, 1)),
      radii_(static_cast<std::size_t>(std::max(slices, 1)), radius) {}

bool TurnedProfile::cut(double axialA, double radialA, double axialB, double radialB,
                        const Cutter& tool) {
    const double noseRadius = tool.radius;
    const int body = tool.radial ? 0 : tool.body;
    for (double v : {axialA, radialA, axialB, radialB})
        if (!std::isfinite(v)) return false;
    if (!(noseRadius >= 0.0)) return false;
    // The slices the nose (or flat tip) reaches, and behind a nose on the
    // insert's side all the slices up to the end of the bar.
    const double low = std::min(axialA, axialB) - noseRadius;
    const double high = std::max(axialA, axialB) + noseRadius;
    const double infinity = std::numeric_limits<double>::infinity();
    const auto [first, last] = cellsWithin(body < 0 ? -infinity : low, body > 0 ? infinity : high,
                                           from_, length_, slices());
    // Outside the bar all along (the insert stands further out): nothing to scan.
    if (std::min(radialA, radialB) - noseRadius > radius_) return false;
    const SweptRowScanner nose(SweptDisc{radialA, axialA, radialB, axialB, noseRadius});
    bool removed = false;
    for (int k = first; k <= last; ++k) {
        const double at = sliceCentre(k);
        const double reach =
            tool.radial ? flatReach(axialA, radialA, axialB, radialB, noseRadius, at)
                        : std::min(noseReach(nose, at), bodyReach(axialA, radialA, axialB, radialB,
                                                                  noseRadius, body, at));
        const double inner = std::max(0.0, reach);
        double& r = radii_[static_cast<std::size_t>(k)];
        if (inner < r) {
            r = inner;
            removed = true;
        }
    }
    return removed;
}

double TurnedProfile::removedVolume() const {
    double sum = 0.0;
    for (double r : radii_)
        sum += radius_ * radius_ - r * r;
    return kPi * sum * length_;
}

}  // namespace mtc::core::removal
