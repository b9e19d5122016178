#pragma once

#include <cstddef>
#include <vector>

namespace mtc::core::motion {

/// The course of a move worked out before it runs (adaptive feed control,
/// docs/decisions/motion.md MOT-011): how far it has come at each moment.
/// Knots of (time, distance), both as shares of the whole move, from (0, 0)
/// to (1, 1); between knots the distance is linear in time. At most
/// kMaxKnots whatever the move's length: when full, every second knot is
/// dropped and the spacing taken from then on doubles.
class TimedCourse {
  public:
    static constexpr std::size_t kMaxKnots = 256;

    /// Records the move at `seconds` after its start, `distance` from it
    /// (both non-decreasing).
    void add(double seconds, double distance);
    /// Ends the record: the last point is the move's end, and the knots
    /// become shares of it. False (and no course) when it took no time or
    /// travelled nothing.
    bool finish(double seconds, double distance);

    /// Where the move is at share `time` (0..1) of its time: the share of
    /// the distance travelled, and d(distance share) / d(time share) there
    /// (1 at a constant velocity). One search of the knots.
    struct Point {
        double distance = 0.0;
        double slope = 1.0;
    };
    Point at(double time) const;
    double distanceAt(double time) const { return at(time).distance; }
    double slopeAt(double time) const { return at(time).slope; }
    std::size_t knotCount() const { return knots_.size(); }

  private:
    struct Knot {
        double time = 0.0;
        double distance = 0.0;
    };
    std::size_t segmentAt(double time) const;
    void thinOut();

    std::vector<Knot> knots_{Knot{}};
    double spacing_ = 0.0;  ///< least time between two recorded knots, s
};

}  // namespace mtc::core::motion
