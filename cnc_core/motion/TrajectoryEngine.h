#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "cnc_core/motion/MotionQueue.h"
#include "cnc_core/motion/SegmentProfile.h"
#include "cnc_core/motion/SpindleSet.h"

namespace mtc::core::motion {

/// Look-ahead depth of the simulated machine in queue entries (MOT-002).
inline constexpr std::size_t kDefaultLookAhead = 32;

/// Moves the axes of one process in time (docs/decisions/motion.md): the
/// interpreter's moves, dwells and actions go into a bounded look-ahead
/// queue; advance() interpolates them under the axes' velocity and
/// acceleration limits with the overrides, feed hold and Control reset of
/// the operator. Every figure is exact at any time (closed-form profiles),
/// so the result does not depend on how the time is cut into ticks as long
/// as the driver refills the queue whenever advance() returns early.
///
/// The driver's loop (panel tick, CLI, tests):
///   while (time left) {
///       while (engine.wantsMore() && the program can go on) step the interpreter;
///       time left -= engine.advance(time left);
///   }
class TrajectoryEngine {
  public:
    explicit TrajectoryEngine(const MotionLimits& limits,
                              std::size_t lookAhead = kDefaultLookAhead);

    // --- input, in program order ---
    /// True while the queue has room for another block: up to the
    /// look-ahead depth, plus the batch (setBatch()).
    bool wantsMore() const { return queue_.size() < queue_.capacity() + batch_; }
    /// The entries queued fill the look-ahead depth: the plan of the move
    /// at the front is complete (batching, MOT-022).
    bool lookAheadFull() const { return queue_.full(); }
    /// Batching (MOT-022): the queue takes `entries` more than the
    /// look-ahead depth, so a driver can interpret a batch of blocks and
    /// then let the machine work them off in one go. Every move is still
    /// planned with the look-ahead window it would have seen without a
    /// batch: the blocks begun while fewer than the depth were queued
    /// behind it. The driver calls beginBlock() before each block and lets
    /// the machine run only while the depth is queued (lookAheadFull()) or
    /// it has nothing more to give. Overrides, hold and single block replan
    /// the whole queue: a batch is for a driver without an operator (the
    /// CLI). 0 (the default): no batch.
    void setBatch(std::size_t entries);
    std::size_t batch() const { return batch_; }
    /// The driver begins a block. Under a batch this closes the look-ahead
    /// window of every move that has the depth or more queued behind it:
    /// without a batch the block would not have been queued before the move
    /// started.
    void beginBlock();
    /// itemsQueued() at the last beginBlock().
    std::uint64_t blockStart() const { return blockStart_; }
    std::size_t lookAhead() const { return queue_.capacity(); }
    /// A G0/G1/G2/G3 move (Motion::start .. Motion::end). A move of length 0
    /// takes no time and is not queued.
    void pushMove(const Motion& motion, BlockTransition mode);
    /// The geometry of `motion`, worked out in the slot its queue entry will
    /// take: a pushMove() of the same, unchanged `motion` right after takes
    /// it as it is (SimulatedMachine reads the path length off it first).
    const SegmentGeometry& prepareMove(const Motion& motion);
    /// A dwell of `seconds` (the axes are at rest during it).
    void pushDwell(const SourceLocation& where, double seconds);
    /// A machine action; its tag is reported by takeReached() when it is executed.
    void pushAction(const SourceLocation& where, const MachineAction& action);
    /// A move whose course is already known (adaptive feed control, MOT-011):
    /// from rest to rest, `fraction` (0..1) of its path in `seconds` at 100 %
    /// override, along `course` (null: at a constant velocity); the feed
    /// (G1/G2/G3) or rapid (G0) override scales its time, feed hold stops it
    /// at once.
    void pushTimedMove(const Motion& motion, double seconds, double fraction,
                       std::shared_ptr<const TimedCourse> course = nullptr);

    // --- time ---
    /// Moves everything on by up to `seconds` and returns the time taken. It
    /// returns early (less than `seconds`) when a queue entry is finished, so
    /// the driver can refill the queue before the planning goes on.
    double advance(double seconds);
    /// advance() called again after every entry it finishes, as a driver
    /// that queues nothing in between calls it (the simulated machine's
    /// loop; one call instead of one per entry, MOT-027): on until the time
    /// is used, the queue is empty or fewer than `keep` entries are queued
    /// (0: until empty). The busy time at the end of each entry it finishes
    /// is appended to `finishedAt`, oldest first. Returns the time used, to
    /// the bit what the driver's loop counts.
    double advanceOver(double seconds, std::size_t keep, std::vector<double>& finishedAt);

    // --- the operator ---
    /// Feed override of G1/G2/G3, 0 .. feedOverrideMax %.
    void setFeedOverride(double percent);
    /// Rapid traverse override of G0, 0 .. 100 %.
    void setRapidOverride(double percent);
    double feedOverride() const { return feedOverride_; }
    double rapidOverride() const { return rapidOverride_; }
    /// Feed hold: the axes brake along the path and stay there.
    void hold();
    /// Continues after hold() from where the axes stand, mid-block.
    void resume();
    bool held() const { return held_; }
    /// Single block (MOT-015): every block ends at rest and the next one
    /// waits for continueAfterBlockStop(). Switched on while moving, the
    /// axes stop at the end of the first block they can still brake for.
    void setStopAtBlockEnds(bool on);
    bool stopsAtBlockEnds() const { return blockStops_; }
    /// The axes stand at the end of a block and the next one waits.
    bool atBlockStop() const { return atBlockStop_; }
    /// Queue items ever queued / done: a caller that notes itemsQueued()
    /// before and after queueing a block knows which items are the block's.
    std::uint64_t itemsQueued() const { return queue_.pushed(); }
    std::uint64_t itemsDone() const { return queue_.popped(); }
    void continueAfterBlockStop() { atBlockStop_ = false; }
    /// Control reset: the axes stop where they are at once, the queue is
    /// emptied, the spindles ramp down, a hold is cleared.
    void stop();
    /// Drops what is queued once the axes are at rest (a released jog key
    /// after the axes braked under hold()); unlike stop() the spindles keep
    /// turning. Returns false (nothing done) while the axes still move.
    bool discardAtRest();

    // --- the state ---
    /// Nothing queued: every move and dwell is done, the axes are at rest.
    bool idle() const { return queue_.empty(); }
    /// Every second advance() was given (since construction or resetClock()).
    double seconds() const { return seconds_; }
    /// Busy time: the seconds something was queued, except where the axes
    /// stood on a move under feed hold or at override 0 % (the operator's
    /// wait, as at M00, is no machine time; docs/decisions/station.md ST-003).
    double busySeconds() const { return busy_; }
    /// Sets seconds() and busySeconds() to 0.
    void resetClock() { seconds_ = busy_ = 0.0; }
    /// How long the queue takes from now if nothing changes (no override
    /// change, no hold; spindle waits not counted); infinite while the axes
    /// stand for good (hold, override 0 %).
    double secondsToDrain() const;
    /// Machine positions (mm, degrees for rotary axes).
    const Position& position() const { return position_; }
    double position(int axis) const;
    /// Sets where the axes are (start, or after a move outside the engine).
    void setPosition(const Position& position) {
        position_ = position;
        stoppedShortOf_.reset();
    }
    /// Path velocity, units/s of the move's plane (0 at rest).
    double velocity() const { return velocity_; }
    /// End of the move being executed minus the position, per axis (0 between
    /// moves). After a move adaptive feed control stopped on its path (509,
    /// 510) and until anything else is queued: what is left of it.
    double distanceToGo(int axis) const;
    /// Where the entry being executed comes from, or the last one executed
    /// when idle or at a single-block stop (built when asked: the queue keeps
    /// no string per entry, MOT-027).
    SourceLocation currentLocation() const;
    /// Forgets the last executed entry (a new run: nothing executed yet).
    void clearLocation() {
        lastWhere_ = {};
        lastBlock_ = 0;
    }
    std::uint32_t currentBlockIndex() const;
    /// True while a move (or timed move) is being executed (its geometry is currentMove()).
    bool moving() const;
    const QueueItem* currentMove() const;
    /// Path distance travelled along the current move (timed moves too).
    double pathPosition() const { return pathS_; }
    /// Share (0 ... 1) of the current move's path travelled; 0 when no move
    /// is being executed.
    double travelledShare() const;
    /// Moves and timed moves in the queue (the one being executed included).
    std::size_t queuedMoves() const;
    const SpindleSet& spindles() const { return spindles_; }
    const MotionLimits& limits() const { return limits_; }
    /// Tags of the actions executed since the last call, oldest first.
    std::vector<std::uint32_t> takeReached();
    /// An action was executed since the last takeReached().
    bool reachedActions() const { return !reached_.empty(); }
    const QueueItem* queued(std::size_t i) const {
        return i < queue_.size() ? &queue_.at(i) : nullptr;
    }
    std::size_t queuedCount() const { return queue_.size(); }

  private:
    /// The cruise velocity of `move` now; QueueItem::cap holds it for every
    /// queued move (worked out when it is queued and on every change of an
    /// override or of the hold, which all go through replanAll()).
    double capOf(const QueueItem& move) const;
    /// The velocity the front move may leave with: its exitLimit, or under
    /// a batch the one of its own look-ahead window once that is closed.
    double frontExit() const {
        const QueueItem& front = queue_.front();
        return batch_ > 0 && front.windowClosed ? front.windowExit : front.exitLimit;
    }
    /// Look-ahead: the velocity each move may leave with, from the end of
    /// the queue backwards (0 at the end). With `early` it stops at the
    /// first move whose limit did not change. Returns true when the front's changed.
    bool planBackward(bool early);
    void replanFront();
    void afterPlanChange(bool frontChanged);
    /// Caps changed (override, hold): the whole queue and the front from where it is.
    void replanAll();
    /// Time passes; `busy` of it counts as busy time.
    void spend(double seconds, double busy);
    /// advance() without its check of `seconds`; `finished`: it returned
    /// because an entry was finished.
    double runFor(double seconds, bool& finished);
    double runMove(QueueItem& move, double room, bool& finished);
    double runDwell(QueueItem& dwell, double room, bool& finished);
    double runAction(QueueItem& action, double room, bool& finished);
    double runTimed(QueueItem& timed, double room, bool& finished);
    /// Override of `item` as a factor (0 under feed hold).
    double rateOf(const QueueItem& item) const;
    void finishFront();
    /// Empties the queue where the axes stand (stop(), discardAtRest()).
    void dropQueue();

    MotionLimits limits_;
    MotionQueue queue_;
    SpindleSet spindles_;
    SegmentProfile profile_;
    bool planned_ = false;  ///< profile_ belongs to the front move
    double profileTime_ = 0.0;
    double plannedExit_ = 0.0;
    double pathS_ = 0.0;
    double velocity_ = 0.0;
    /// Machine end of the last entry when it was a timed move stopped on its
    /// path (it did not reach it); empty otherwise.
    std::optional<Position> stoppedShortOf_;
    double dwelt_ = 0.0;          ///< seconds of the front dwell (timed move at 100 %) done
    bool actionApplied_ = false;  ///< the front action's spindle change is made
    Position position_{};
    double seconds_ = 0.0;
    double busy_ = 0.0;
    double feedOverride_ = 100.0;
    double rapidOverride_ = 100.0;
    bool held_ = false;
    bool blockStops_ = false;   ///< single block: rest at each block's end
    bool atBlockStop_ = false;  ///< waiting there for continueAfterBlockStop()
    QueuedLocation lastWhere_;
    std::uint32_t lastBlock_ = 0;
    std::vector<std::uint32_t> reached_;
    std::size_t batch_ = 0;              ///< entries beyond the look-ahead depth (setBatch)
    std::uint64_t blockStart_ = 0;       ///< itemsQueued() at the last beginBlock()
    std::uint64_t windowsOpenFrom_ = 0;  ///< first item whose look-ahead window is open
    /// What prepareMove() left: the motion, the slot holding its geometry
    /// and the pushes so far. Only a push writes a slot, so while no push
    /// came in between and the slot did not move, the geometry is there.
    struct Prepared {
        const Motion* motion = nullptr;
        const QueueItem* slot = nullptr;
        std::uint64_t pushed = 0;
    };
    /// The prepared geometry of `motion` when it is still in the next slot.
    const SegmentGeometry* preparedGeometry(const Motion& motion);
    Prepared prepared_;
};

}  // namespace mtc::core::motion
