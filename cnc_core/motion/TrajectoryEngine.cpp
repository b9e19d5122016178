#include "cnc_core/motion/TrajectoryEngine.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace mtc::core::motion {

namespace {
constexpr double kForever = std::numeric_limits<double>::infinity();

}  // namespace

TrajectoryEngine::TrajectoryEngine(const MotionLimits& limits, std::size_t lookAhead)
    : limits_(limits), queue_(lookAhead), spindles_(limits) {}

void TrajectoryEngine::setBatch(std::size_t entries) {
    batch_ = entries;
    // Room for a full batch and a block's usual overfill without growing
    // (every slot beyond costs first-level cache, MOT-022).
    queue_.reserve(queue_.capacity() + entries + 2);
}

void TrajectoryEngine::beginBlock() {
    blockStart_ = queue_.pushed();
    if (batch_ == 0) return;
    // Item n would have started before this block was queued when n + depth
    // <= blockStart_: its plan over what is queued now is the one it gets.
    const std::uint64_t depth = queue_.capacity();
    windowsOpenFrom_ = std::max(windowsOpenFrom_, queue_.popped());
    for (; windowsOpenFrom_ + depth <= blockStart_; ++windowsOpenFrom_) {
        QueueItem& item = queue_.at(static_cast<std::size_t>(windowsOpenFrom_ - queue_.popped()));
        item.windowExit = item.exitLimit;
        item.windowClosed = true;
    }
}

// ----------------------------------------------------------------- input

const SegmentGeometry& TrajectoryEngine::prepareMove(const Motion& motion) {
    QueueItem& slot = queue_.nextSlot();
    slot.geometry.describe(motion, limits_);
    prepared_ = {&motion, &slot, queue_.pushed()};
    return slot.geometry;
}

const SegmentGeometry* TrajectoryEngine::preparedGeometry(const Motion& motion) {
    const QueueItem& slot = queue_.nextSlot();
    const bool still = prepared_.motion == &motion && prepared_.slot == &slot &&
                       prepared_.pushed == queue_.pushed();
    prepared_ = {};
    return still ? &slot.geometry : nullptr;
}

void TrajectoryEngine::pushMove(const Motion& motion, BlockTransition mode) {
    // The geometry is worked out where the entry is queued (no copy of it).
    const SegmentGeometry* prepared = preparedGeometry(motion);
    const SegmentGeometry& geometry = prepared ? *prepared : prepareMove(motion);
    prepared_ = {};
    if (!(geometry.length() > 1e-12)) return;  // nothing moves: no time, no stop
    const QueueItem* before = queue_.moveBeforeEnd();
    double entry = 0.0;
    const bool rapid = motion.type == MotionType::Rapid;
    if (before != nullptr)
        entry = junctionVelocity({&before->geometry, before->rapid, before->mode},
                                 {&geometry, rapid, mode}, limits_);
    QueueItem& item = queue_.pushBack();  // the slot that holds `geometry`
    item.kind = QueueItem::Kind::Move;
    item.where.assign(motion.where);
    item.blockIndex = motion.blockIndex;
    item.limits = pathLimits(item.geometry, limits_);
    item.rapid = rapid;
    item.mode = mode;
    item.feed = rapid ? 0.0 : std::max(0.0, motion.feed) / 60.0;
    item.cap = capOf(item);
    item.entryLimit = entry;
    item.exitLimit = 0.0;
    item.windowClosed = false;
    afterPlanChange(planBackward(true));
}

void TrajectoryEngine::pushDwell(const SourceLocation& where, double seconds) {
    QueueItem& item = queue_.pushBack();
    item.kind = QueueItem::Kind::Dwell;
    item.where.assign(where);
    item.seconds = std::isfinite(seconds) ? std::max(0.0, seconds) : 0.0;
}

void TrajectoryEngine::pushAction(const SourceLocation& where, const MachineAction& action) {
    QueueItem& item = queue_.pushBack();
    item.kind = QueueItem::Kind::Action;
    item.where.assign(where);
    item.action = action;
}

void TrajectoryEngine::pushTimedMove(const Motion& motion, double seconds, double fraction,
                                     std::shared_ptr<const TimedCourse> course) {
    QueueItem& item = queue_.pushBack();
    item.kind = QueueItem::Kind::Timed;
    item.where.assign(motion.where);
    item.blockIndex = motion.blockIndex;
    item.geometry.describe(motion, limits_);
    item.rapid = motion.type == MotionType::Rapid;
    item.seconds = std::isfinite(seconds) ? std::max(0.0, seconds) : 0.0;
    item.fraction = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 1.0;
    item.course = std::move(course);
}

// --------------------------------------------------------------- planning

double TrajectoryEngine::capOf(const QueueItem& move) const {
    if (held_) return 0.0;
    if (move.rapid) return move.limits.velocity * rapidOverride_ / 100.0;
    return std::min(move.feed * feedOverride_ / 100.0, move.limits.velocity);
}

bool TrajectoryEngine::planBackward(bool early) {
    double following = 0.0;  // largest velocity at the start of what follows
    bool frontChanged = false;
    bool last = true;
    for (std::size_t i = queue_.size(); i-- > 0;) {
        QueueItem& item = queue_.at(i);
        if (blockStops_ && i + 1 < queue_.size() && !item.where.sameBlock(queue_.at(i + 1).where))
            following = 0.0;  // single block: at rest where the next block begins
        if (item.kind != QueueItem::Kind::Move) {  // the usual kind tested once (MOT-026)
            if (item.kind != QueueItem::Kind::Action || item.action.stopsPath) {
                following = 0.0;  // a dwell, a timed move or an action the path stops at
                last = false;
            }
            continue;
        }
        const bool unchanged = item.exitLimit == following;
        if (early && unchanged && !last) break;  // everything before stays as planned
        last = false;
        item.exitLimit = following;
        if (i == 0) {
            frontChanged = !unchanged || !planned_ || plannedExit_ != following;
            break;
        }
        // min(entry, cap, reach) with reach >= 0 (or NaN): a move that starts
        // at rest (a corner) bounds it to 0 whatever it can reach, and the
        // square root on the chain from move to move is skipped (MOT-023).
        const double bound = std::min(item.entryLimit, item.cap);
        if (bound <= 0.0) {
            following = bound;
            continue;
        }
        const double reach = std::sqrt(following * following +
                                       2.0 * item.limits.acceleration * item.geometry.length());
        following = std::min(bound, reach);
    }
    return frontChanged;
}

// Inline where it is called: runMove() plans every move once (MOT-028).
[[gnu::always_inline]] inline void TrajectoryEngine::replanFront() {
    if (queue_.empty() || queue_.front().kind != QueueItem::Kind::Move) return;
    const QueueItem& move = queue_.front();
    const double length = move.geometry.length() - pathS_;
    const double exit = frontExit();
    profile_.plan(pathS_, velocity_, length, move.cap, exit, move.limits.acceleration);
    plannedExit_ = exit;
    profileTime_ = 0.0;
    planned_ = true;
}

void TrajectoryEngine::afterPlanChange(bool frontChanged) {
    if (!planned_) return;
    // Under a batch what is queued behind the front's window leaves it as planned.
    if (batch_ == 0 ? frontChanged : frontExit() != plannedExit_) replanFront();
}

void TrajectoryEngine::replanAll() {
    for (std::size_t i = 0; i < queue_.size(); ++i) {  // an override or the hold changed
        QueueItem& item = queue_.at(i);
        if (item.kind == QueueItem::Kind::Move) item.cap = capOf(item);
    }
    planBackward(false);
    if (planned_) replanFront();
}

// ------------------------------------------------------------------- time

void TrajectoryEngine::spend(double seconds, double busy) {
    seconds_ += seconds;
    busy_ += busy;
    spindles_.advance(seconds);
}

[[gnu::always_inline]] inline double TrajectoryEngine::runFor(double seconds, bool& finished) {
    double remaining = seconds;
    while (remaining > 0.0) {
        if (queue_.empty()) {
            spend(remaining, 0.0);
            return seconds;
        }
        if (atBlockStop_) {  // the axes stand, time passes without work
            spend(remaining, 0.0);
            return seconds;
        }
        QueueItem& item = queue_.front();
        double used = 0.0;
        switch (item.kind) {
            case QueueItem::Kind::Move:
                used = runMove(item, remaining, finished);
                break;
            case QueueItem::Kind::Dwell:
                used = runDwell(item, remaining, finished);
                break;
            case QueueItem::Kind::Action:
                used = runAction(item, remaining, finished);
                break;
            case QueueItem::Kind::Timed:
                used = runTimed(item, remaining, finished);
                break;
        }
        remaining = used >= remaining ? 0.0 : remaining - used;
        if (finished) {
            finishFront();
            if (remaining > 0.0) return seconds - remaining;
        }
    }
    return seconds;
}

double TrajectoryEngine::advance(double seconds) {
    if (!(seconds > 0.0) || !std::isfinite(seconds)) return 0.0;
    bool finished = false;
    return runFor(seconds, finished);
}

double TrajectoryEngine::advanceOver(double seconds, std::size_t keep,
                                     std::vector<double>& finishedAt) {
    // The driver's loop: left = what advance(left) left over, after each call.
    double left = seconds;
    while (left > 0.0) {
        bool finished = false;
        const double used = std::isfinite(left) ? runFor(left, finished) : 0.0;
        left = used >= left ? 0.0 : left - used;
        if (finished) finishedAt.push_back(busy_);
        if (queue_.size() < keep || queue_.empty()) break;
    }
    return seconds - left;
}

// Inline in runFor(), which advance() and advanceOver() both inline (MOT-027).
[[gnu::always_inline]] inline double TrajectoryEngine::runMove(QueueItem& move, double room,
                                                               bool& finished) {
    if (!planned_) replanFront();
    const double left = profile_.reachesEnd() ? profile_.duration() - profileTime_ : kForever;
    if (left <= room) {
        spend(std::max(0.0, left), std::max(0.0, left));
        move.geometry.machinePoint(move.geometry.length(), position_);
        velocity_ = profile_.endVelocity();
        finished = true;
        return std::max(0.0, left);
    }
    // A profile that comes to rest short of the end (hold, override 0 %)
    // stands after its duration: the braking is busy time, the standstill not.
    const double busy =
        profile_.reachesEnd() ? room : std::clamp(profile_.duration() - profileTime_, 0.0, room);
    spend(room, busy);
    profileTime_ += room;
    profile_.sample(profileTime_, pathS_, velocity_);
    move.geometry.machinePoint(pathS_, position_);
    return room;
}

double TrajectoryEngine::runDwell(QueueItem& dwell, double room, bool& finished) {
    const double left = dwell.seconds - dwelt_;
    if (left <= room) {
        spend(std::max(0.0, left), std::max(0.0, left));
        finished = true;
        return std::max(0.0, left);
    }
    spend(room, room);
    dwelt_ += room;
    return room;
}

double TrajectoryEngine::runAction(QueueItem& item, double room, bool& finished) {
    const MachineAction& action = item.action;
    if (!actionApplied_) {
        if (action.speed >= 0.0) spindles_.setSpeed(action.spindle, action.speed);
        if (action.rotation >= 0)
            spindles_.setRotation(action.spindle,
                                  static_cast<SpindleSet::Rotation>(action.rotation));
        actionApplied_ = true;
    }
    if (!action.waitForSpindle || spindles_.atSpeed(action.spindle)) {
        finished = true;
        return 0.0;
    }
    const double left = spindles_.secondsToSpeed(action.spindle);
    if (left <= room) {
        spend(left, left);
        finished = spindles_.atSpeed(action.spindle);
        return left;
    }
    spend(room, room);
    return room;
}

double TrajectoryEngine::rateOf(const QueueItem& item) const {
    if (held_) return 0.0;
    return (item.rapid ? rapidOverride_ : feedOverride_) / 100.0;
}

double TrajectoryEngine::runTimed(QueueItem& timed, double room, bool& finished) {
    const double travel = timed.fraction * timed.geometry.length();
    const double rate = rateOf(timed);
    const double left = timed.seconds - dwelt_;
    if (!(left > 0.0) || (rate > 0.0 && left / rate <= room)) {
        const double used = left > 0.0 ? left / rate : 0.0;
        spend(used, used);
        dwelt_ = timed.seconds;
        timed.geometry.machinePoint(travel, position_);
        velocity_ = 0.0;
        finished = true;
        return used;
    }
    if (rate > 0.0) {
        spend(room, room);
        dwelt_ += room * rate;
    } else {
        spend(room, 0.0);  // held or at 0 %: the axes stand
    }
    const double share = dwelt_ / timed.seconds;
    const TimedCourse::Point course =
        timed.course ? timed.course->at(share) : TimedCourse::Point{share, 1.0};
    pathS_ = travel * course.distance;  // pathPosition() of a timed move too
    timed.geometry.machinePoint(pathS_, position_);
    velocity_ = travel / timed.seconds * course.slope * rate;
    return room;
}

[[gnu::always_inline]] inline void TrajectoryEngine::finishFront() {
    QueueItem& item = queue_.front();
    // lastWhere_ is read only while nothing is queued or at a single-block
    // stop, and by the single-block test below: kept for those (MOT-027).
    if (blockStops_ || queue_.size() == 1) lastWhere_ = item.where;
    lastBlock_ = item.blockIndex;
    if (item.kind == QueueItem::Kind::Action) reached_.push_back(item.action.tag);
    if (item.kind == QueueItem::Kind::Timed && item.fraction < 1.0)
        stoppedShortOf_ = item.geometry.machineEnd();
    else
        stoppedShortOf_.reset();
    const bool flowsOut = item.kind == QueueItem::Kind::Move ||  // Timed ends at rest
                          (item.kind == QueueItem::Kind::Action && !item.action.stopsPath);
    queue_.popFront();
    planned_ = false;
    pathS_ = 0.0;
    dwelt_ = 0.0;
    actionApplied_ = false;
    // Velocity flows only from a move into the next one (across transparent
    // actions); anything else starts at rest.
    const bool flowsOn =
        !queue_.empty() &&
        (queue_.front().kind == QueueItem::Kind::Move ||
         (queue_.front().kind == QueueItem::Kind::Action && !queue_.front().action.stopsPath));
    if (!flowsOut || !flowsOn) velocity_ = 0.0;
    // Single block: wait before the next block when the axes are at rest
    // (switched on too late to brake, they go on to the next block's end).
    if (blockStops_ && !queue_.empty() && !lastWhere_.sameBlock(queue_.front().where) &&
        std::abs(velocity_) < 1e-9) {
        velocity_ = 0.0;
        atBlockStop_ = true;
    }
}

// --------------------------------------------------------------- operator

void TrajectoryEngine::setFeedOverride(double percent) {
    if (!std::isfinite(percent)) return;
    feedOverride_ = std::clamp(percent, 0.0, limits_.feedOverrideMax);
    replanAll();
}

void TrajectoryEngine::setRapidOverride(double percent) {
    if (!std::isfinite(percent)) return;
    rapidOverride_ = std::clamp(percent, 0.0, limits_.rapidOverrideMax);
    replanAll();
}

void TrajectoryEngine::hold() {
    if (held_) return;
    held_ = true;
    replanAll();
}

void TrajectoryEngine::resume() {
    if (!held_) return;
    held_ = false;
    replanAll();
}

void TrajectoryEngine::setStopAtBlockEnds(bool on) {
    if (on == blockStops_) return;
    blockStops_ = on;
    if (!on) atBlockStop_ = false;
    replanAll();
}

void TrajectoryEngine::dropQueue() {
    if (!queue_.empty()) {
        lastWhere_ = queue_.front().where;
        lastBlock_ = queue_.front().blockIndex;
    }
    queue_.clear();
    stoppedShortOf_.reset();
    planned_ = false;
    pathS_ = velocity_ = dwelt_ = 0.0;
    actionApplied_ = false;
    held_ = false;
    atBlockStop_ = false;
}

bool TrajectoryEngine::discardAtRest() {
    if (std::abs(velocity_) > 1e-9) return false;
    dropQueue();
    return true;
}

void TrajectoryEngine::stop() {
    dropQueue();
    spindles_.stopAll();
}

// ------------------------------------------------------------------ state

double TrajectoryEngine::secondsToDrain() const {
    double total = 0.0;
    double v = velocity_;  // velocity carried into the next move
    for (std::size_t i = 0; i < queue_.size(); ++i) {
        const QueueItem& item = queue_.at(i);
        const double done = i == 0 ? dwelt_ : 0.0;
        switch (item.kind) {
            case QueueItem::Kind::Move: {
                SegmentProfile profile;
                const double s = i == 0 ? pathS_ : 0.0;
                profile.plan(s, v, item.geometry.length() - s, item.cap, item.exitLimit,
                             item.limits.acceleration);
                if (!profile.reachesEnd()) return kForever;
                total += profile.duration();
                v = profile.endVelocity();
                break;
            }
            case QueueItem::Kind::Dwell:
                total += std::max(0.0, item.seconds - done);
                v = 0.0;
                break;
            case QueueItem::Kind::Timed: {
                const double rate = rateOf(item);
                if (!(rate > 0.0)) return kForever;
                total += std::max(0.0, item.seconds - done) / rate;
                v = 0.0;
                break;
            }
            case QueueItem::Kind::Action:
                if (item.action.stopsPath) v = 0.0;
                break;
        }
    }
    return total;
}

double TrajectoryEngine::position(int axis) const {
    return axis >= 0 && axis < kMaxAxes ? position_[static_cast<std::size_t>(axis)] : 0.0;
}

bool TrajectoryEngine::moving() const {
    return !queue_.empty() && !atBlockStop_ &&
           (queue_.front().kind == QueueItem::Kind::Move ||
            queue_.front().kind == QueueItem::Kind::Timed);
}

const QueueItem* TrajectoryEngine::currentMove() const {
    return moving() ? &queue_.front() : nullptr;
}

double TrajectoryEngine::travelledShare() const {
    const QueueItem* move = currentMove();
    if (move == nullptr || !(move->geometry.length() > 0.0)) return 0.0;
    return std::clamp(pathS_ / move->geometry.length(), 0.0, 1.0);
}

std::size_t TrajectoryEngine::queuedMoves() const {
    std::size_t moves = 0;
    for (std::size_t i = 0; i < queue_.size(); ++i) {
        const QueueItem::Kind kind = queue_.at(i).kind;
        if (kind == QueueItem::Kind::Move || kind == QueueItem::Kind::Timed) ++moves;
    }
    return moves;
}

double TrajectoryEngine::distanceToGo(int axis) const {
    if (axis < 0 || axis >= kMaxAxes) return 0.0;
    const auto k = static_cast<std::size_t>(axis);
    if (queue_.empty() && stoppedShortOf_) return (*stoppedShortOf_)[k] - position_[k];
    const QueueItem* move = currentMove();
    if (move == nullptr || axis >= move->geometry.axisCount()) return 0.0;
    return move->geometry.machineEnd()[k] - position_[k];
}

SourceLocation TrajectoryEngine::currentLocation() const {
    // At a single-block stop the block just finished is the one shown.
    return (queue_.empty() || atBlockStop_ ? lastWhere_ : queue_.front().where).location();
}

std::uint32_t TrajectoryEngine::currentBlockIndex() const {
    return queue_.empty() || atBlockStop_ ? lastBlock_ : queue_.front().blockIndex;
}

std::vector<std::uint32_t> TrajectoryEngine::takeReached() {
    if (reached_.empty()) return {};  // after nearly every move: nothing to swap
    std::vector<std::uint32_t> out;
    out.swap(reached_);
    return out;
}

}  // namespace mtc::core::motion
