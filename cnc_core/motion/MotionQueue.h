#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "cnc_core/motion/JunctionRule.h"
#include "cnc_core/motion/PathLimits.h"
#include "cnc_core/motion/QueuedLocation.h"
#include "cnc_core/motion/TimedCourse.h"

namespace mtc::core::motion {

/// A machine action between moves (an auxiliary function the SPS
/// acknowledges, a spindle command, a command of the interpreter).
struct MachineAction {
    int spindle = 0;              ///< 1..3; 0 = no spindle
    double speed = -1.0;          ///< new commanded speed, rpm; < 0 = unchanged
    int rotation = -1;            ///< SpindleSet::Rotation as int; -1 = unchanged
    bool waitForSpindle = false;  ///< the program waits until the spindle is at speed
    bool stopsPath = true;        ///< the axes come to rest before it (MOT-007)
    std::uint32_t tag = 0;        ///< the caller's id, reported when the action is reached
};

/// One entry of the look-ahead queue.
struct QueueItem {
    /// Timed: a move whose course was worked out when it was queued (adaptive
    /// feed control, docs/decisions/motion.md MOT-011): it starts and ends at
    /// rest and travels `fraction` of its path in `seconds` (at 100 %
    /// override) along `course` (the controller's feed over time), at a
    /// constant velocity when it has none.
    enum class Kind : std::uint8_t { Move, Dwell, Action, Timed };
    Kind kind = Kind::Move;
    QueuedLocation where;  ///< no string per entry (MOT-027)
    std::uint32_t blockIndex = 0;
    // Move:
    PathLimits limits;
    bool rapid = false;
    BlockTransition mode;
    double feed = 0.0;  ///< programmed path feed, plane units/s (0 for G0)
    /// Cruise velocity at the overrides and hold in force (the engine's
    /// capOf(), kept up to date by the engine when they change, MOT-026).
    double cap = 0.0;
    double entryLimit = 0.0;  ///< junction velocity with the move before (0: starts at rest)
    double exitLimit = 0.0;   ///< planned velocity at the end (look-ahead), plane units/s
    /// Batching (MOT-022): the exit velocity planned over the move's own
    /// look-ahead window, once that window is closed (windowClosed).
    double windowExit = 0.0;
    bool windowClosed = false;
    // Dwell, Timed:
    double seconds = 0.0;
    // Timed:
    double fraction = 1.0;  ///< share of the path travelled (< 1: stopped on the path)
    std::shared_ptr<const TimedCourse> course;  ///< null: constant velocity
    // Action:
    MachineAction action;
    // Move, Timed: last, after the fields every entry uses (MOT-023).
    SegmentGeometry geometry;
};

/// The bounded look-ahead queue: a ring of items in program order.
/// `capacity` is the look-ahead depth; a block may overfill it (one block
/// can give several items), the storage then grows once and stays.
class MotionQueue {
  public:
    explicit MotionQueue(std::size_t capacity);

    std::size_t capacity() const { return capacity_; }
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    bool full() const { return size_ >= capacity_; }
    QueueItem& at(std::size_t i) { return storage_[slot(i)]; }
    const QueueItem& at(std::size_t i) const { return storage_[slot(i)]; }
    QueueItem& front() { return at(0); }
    const QueueItem& front() const { return at(0); }
    /// A new item at the end (grows the storage when it is full). It is the
    /// slot nextSlot() returned, unless the queue changed in between.
    QueueItem& pushBack();
    /// The slot the next pushBack() returns, as its last use left it (grows
    /// the storage when it is full): an item can be worked out in place
    /// before it is known whether it is queued at all.
    QueueItem& nextSlot() {
        if (size_ == slots_) grow();
        return storage_[slot(size_)];
    }
    void popFront();
    /// Storage for at least `items` entries without growing (batching).
    void reserve(std::size_t items);
    void clear() {
        head_ = size_ = 0;
        popped_ = pushed_;
    }
    /// Items ever pushed / done (popped or cleared): item n (0-based, in
    /// push order) is in the queue while popped() <= n < pushed().
    std::uint64_t pushed() const { return pushed_; }
    std::uint64_t popped() const { return popped_; }
    /// The last move in the queue with only transparent actions after it, or nullptr.
    const QueueItem* moveBeforeEnd() const;

  private:
    /// Doubles the storage, the items moved to its start in queue order.
    void grow();
    /// `slots` of storage, the items moved to its start in queue order.
    void regrow(std::size_t slots);
    /// Storage index of item `i` < storage size: one wrap at most, so a
    /// subtraction instead of a division (the planner walks the queue on
    /// every move).
    std::size_t slot(std::size_t i) const {
        const std::size_t index = head_ + i;
        return index < slots_ ? index : index - slots_;
    }

    std::vector<QueueItem> storage_;
    /// storage_.size(), kept: the vector's size is a division by the
    /// item's size, on every slot() (MOT-026).
    std::size_t slots_ = 0;
    std::size_t capacity_;
    std::size_t head_ = 0, size_ = 0;
    std::uint64_t pushed_ = 0, popped_ = 0;
};

}  // namespace mtc::core::motion
