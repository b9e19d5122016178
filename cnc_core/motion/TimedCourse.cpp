#include "cnc_core/motion/TimedCourse.h"

#include <algorithm>
#include <cmath>

namespace mtc::core::motion {

void TimedCourse::add(double seconds, double distance) {
    if (!std::isfinite(seconds) || !std::isfinite(distance)) return;
    const Knot& last = knots_.back();
    if (seconds <= last.time || seconds - last.time < spacing_) return;
    knots_.push_back({seconds, std::max(distance, last.distance)});
    if (knots_.size() >= kMaxKnots) thinOut();
}

void TimedCourse::thinOut() {
    // Keep the even knots; the start stays, the end is added by finish().
    std::size_t kept = 0;
    for (std::size_t i = 0; i < knots_.size(); i += 2)
        knots_[kept++] = knots_[i];
    knots_.resize(kept);
    // From now on at least the mean spacing of what was kept, doubling with each thinning.
    spacing_ = spacing_ > 0.0 ? 2.0 * spacing_ : knots_.back().time / static_cast<double>(kept);
}

bool TimedCourse::finish(double seconds, double distance) {
    if (!(seconds > 0.0) || !(distance > 0.0) || !std::isfinite(seconds) ||
        !std::isfinite(distance)) {
        knots_.assign(1, Knot{});
        return false;
    }
    while (!knots_.empty() && knots_.back().time >= seconds)
        knots_.pop_back();
    knots_.push_back({seconds, distance});
    if (knots_.front().time > 0.0) knots_.insert(knots_.begin(), Knot{});
    for (Knot& k : knots_) {
        k.time /= seconds;
        k.distance = std::clamp(k.distance / distance, 0.0, 1.0);
    }
    return true;
}

std::size_t TimedCourse::segmentAt(double time) const {
    // The knot the segment starts at: the last one at or before `time`.
    const auto after = std::upper_bound(knots_.begin(), knots_.end(), time,
                                        [](double t, const Knot& k) { return t < k.time; });
    const auto index = static_cast<std::size_t>(after - knots_.begin());
    return std::clamp<std::size_t>(index, 1, knots_.size() - 1) - 1;
}

TimedCourse::Point TimedCourse::at(double time) const {
    if (knots_.size() < 2) return {std::clamp(time, 0.0, 1.0), 1.0};
    const std::size_t i = segmentAt(time);
    const Knot& a = knots_[i];
    const Knot& b = knots_[i + 1];
    const double rise = b.distance - a.distance, run = b.time - a.time;
    const double t = std::clamp((time - a.time) / run, 0.0, 1.0);
    return {a.distance + rise * t, rise / run};
}

}  // namespace mtc::core::motion
