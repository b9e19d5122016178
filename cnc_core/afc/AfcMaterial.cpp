#include "cnc_core/afc/AfcMaterial.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/interp/MotionPath.h"

namespace mtc::core {
namespace {

constexpr int kArcPoints = 32;

/// Clips the parameter interval [t0, t1] of p(t) = a + t (b - a) to the slab
/// low <= p <= high of one coordinate.
void clipSlab(double a, double b, double low, double high, double& t0, double& t1) {
    const double d = b - a;
    if (std::fabs(d) < 1e-12) {
        if (a < low || a > high) t1 = -1.0;  // parallel and outside: empty
        return;
    }
    double enter = (low - a) / d, leave = (high - a) / d;
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
}

}  // namespace

AfcMaterial::AfcMaterial(const ProcessConfig& config) : stock_(stockOf(config)) {
    for (std::size_t i = 0; i < config.axes.size() && i < kMaxAxes; ++i) {
        const AxisConfig& axis = config.axes[i];
        if (axis.kind != AxisKind::Linear || axis.definitions.empty()) continue;
        const std::string& d = axis.definitions.front();
        const int scene = d == "X" ? 0 : d == "Y" ? 1 : d == "Z" ? 2 : -1;
        if (scene >= 0 && axisOfScene_[static_cast<std::size_t>(scene)] < 0)
            axisOfScene_[static_cast<std::size_t>(scene)] = static_cast<int>(i);
    }
}

std::array<double, 3> AfcMaterial::scenePoint(const std::array<double, kMaxAxes>& machine) const {
    std::array<double, 3> p{0, 0, 0};
    for (std::size_t d = 0; d < 3; ++d)
        if (axisOfScene_[d] >= 0) p[d] = machine[static_cast<std::size_t>(axisOfScene_[d])];
    return p;
}

bool AfcMaterial::inside(const std::array<double, 3>& p) const {
    if (stock_.shape == Stock::Shape::Block) {
        for (std::size_t d = 0; d < 3; ++d)
            if (p[d] < stock_.min[d] || p[d] > stock_.max[d]) return false;
        return true;
    }
    const auto along = static_cast<std::size_t>(stock_.axis);
    const std::size_t u = (along + 1) % 3, v = (along + 2) % 3;
    return p[along] >= stock_.from && p[along] <= stock_.to &&
           std::hypot(p[u], p[v]) <= stock_.radius;
}

MaterialShare AfcMaterial::alongLine(const std::array<double, 3>& a,
                                     const std::array<double, 3>& b) const {
    double t0 = 0.0, t1 = 1.0;
    if (stock_.shape == Stock::Shape::Block) {
        for (std::size_t d = 0; d < 3 && t0 <= t1; ++d)
            clipSlab(a[d], b[d], stock_.min[d], stock_.max[d], t0, t1);
        return t0 <= t1 ? MaterialShare{t0, t1} : MaterialShare{};
    }
    const auto along = static_cast<std::size_t>(stock_.axis);
    clipSlab(a[along], b[along], stock_.from, stock_.to, t0, t1);
    if (t0 > t1) return {};
    // |q(t)| <= r for the two coordinates across the cylinder axis.
    const std::size_t u = (along + 1) % 3, v = (along + 2) % 3;
    const double du = b[u] - a[u], dv = b[v] - a[v];
    const double qa = du * du + dv * dv, qb = 2 * (a[u] * du + a[v] * dv);
    const double qc = a[u] * a[u] + a[v] * a[v] - stock_.radius * stock_.radius;
    if (qa < 1e-18) return qc <= 0 ? MaterialShare{t0, t1} : MaterialShare{};
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) return {};
    const double root = std::sqrt(disc);
    t0 = std::max(t0, (-qb - root) / (2 * qa));
    t1 = std::min(t1, (-qb + root) / (2 * qa));
    return t0 <= t1 ? MaterialShare{t0, t1} : MaterialShare{};
}

MaterialShare AfcMaterial::along(const Motion& motion) const {
    if (!known()) return {0.0, 1.0};
    const bool arc = motion.type == MotionType::ArcCW || motion.type == MotionType::ArcCCW;
    if (!arc) return alongLine(scenePoint(motion.start), scenePoint(motion.end));
    // Most arcs lie wholly outside or (on a block) wholly inside the stock:
    // their box decides all 32 points at once. The box is the full circle's
    // across the plane and start..end along the other axes, a little wider
    // (outside) or narrower (inside) than needed so rounding cannot matter.
    std::array<double, kMaxAxes> low = motion.start, high = motion.start;
    for (int i = 0; i < motion.axisCount && i < kMaxAxes; ++i) {
        low[i] = std::min(motion.start[i], motion.end[i]);
        high[i] = std::max(motion.start[i], motion.end[i]);
    }
    const int a = motion.planeAxis1, b = motion.planeAxis2;
    if (a < 0 || b < 0 || a >= kMaxAxes || b >= kMaxAxes) return alongArc(motion);
    const double radius =
        std::hypot(motion.start[a] - motion.center1, motion.start[b] - motion.center2);
    low[a] = motion.center1 - radius;
    high[a] = motion.center1 + radius;
    low[b] = motion.center2 - radius;
    high[b] = motion.center2 + radius;
    const std::array<double, 3> from = scenePoint(low), to = scenePoint(high);
    std::array<double, 3> stockLow{}, stockHigh{};
    stock_.box(stockLow, stockHigh);
    constexpr double kMargin = 1e-9;
    bool disjoint = false, within = stock_.shape == Stock::Shape::Block;
    for (std::size_t d = 0; d < 3; ++d) {
        disjoint = disjoint || from[d] - kMargin > stockHigh[d] || to[d] + kMargin < stockLow[d];
        within = within && from[d] - kMargin >= stockLow[d] && to[d] + kMargin <= stockHigh[d];
    }
    if (disjoint) return {1.0, 0.0};  // no point inside, as alongArc says then
    if (within) return {0.0, 1.0};
    return alongArc(motion);
}

MaterialShare AfcMaterial::alongArc(const Motion& motion) const {
    MaterialShare share{1.0, 0.0};
    for (int i = 0; i <= kArcPoints; ++i) {
        const double t = static_cast<double>(i) / kArcPoints;
        if (!inside(scenePoint(motionPointAt(motion, t)))) continue;
        share.from = std::min(share.from, t);
        share.to = std::max(share.to, t);
    }
    return share;
}

}  // namespace mtc::core
