#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "cnc_core/afc/AfcMotion.h"
#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/motion/TrajectoryEngine.h"

namespace mtc::core {

class AdaptiveFeedControl;
class AfcMaterial;
class AfcTrendRecorder;

/// Simulated duration of one move in seconds: feed moves take their path
/// length (straight line or arc in the plane, plus the helical share of the
/// other linear axes) at the programmed feed; rapid moves take as long as the
/// slowest axis needs at its max_velocity. Rotary axes count in degrees.
/// Returns 0 for a move of length 0 and for feed moves without a feed.
double motionSeconds(const Motion& motion, const ProcessConfig& config);
/// The same with the move's path length (motionPathLength) known to the caller.
double motionSeconds(const Motion& motion, const ProcessConfig& config, double length);

/// The machine behind a station's interpreter (cnc_core/cell/Station): it
/// takes every output into the bounded look-ahead queue of the trajectory
/// engine (cnc_core/motion, docs/decisions/motion.md) and works it off in
/// simulated time when the station calls advance(): the axes move
/// continuously under their velocity and acceleration limits, auxiliary
/// functions and commands happen when the machine reaches them, in program
/// order with the moves. The contract the station relies on (TEAM.md,
/// station <-> motion):
///  - the interpreter may send the next block while wantsMore() is true; a
///    block's outputs are always taken, even when they overfill the queue;
///  - advance(dt) moves on by at most dt and returns the time it used; it
///    returns early the moment the queue has room again (when it had none;
///    under a batch, MOT-022: the moment fewer than the look-ahead depth
///    are queued) or runs empty, so the station refills it at exactly that
///    simulated instant. The result does not depend on how the time is cut into
///    advance() calls (the CLI advances in one call what the panel does in
///    20 ms ticks);
///  - seconds() counts only busy time (moving, dwelling, waiting for a
///    spindle): a program takes the same simulated time whether the operator
///    waits at M00 or holds the feed or not;
///  - hold() brakes the axes on the path, resume() goes on mid-block,
///    stop() (Control reset) stops them at once and empties the queue.
/// Moves under adaptive feed control (G26, ITM) keep their bounded
/// simulation (cnc_core/afc/AfcMotion.h): worked out when queued, executed
/// as a timed move from rest to rest (MOT-011).
class SimulatedMachine : public MachineSink {
  public:
    explicit SimulatedMachine(const ProcessConfig& config);
    ~SimulatedMachine() override;
    SimulatedMachine(const SimulatedMachine&) = delete;
    SimulatedMachine& operator=(const SimulatedMachine&) = delete;

    void motion(const Motion& motion) override;
    void auxiliary(const AuxOutput& output) override;
    void dwell(const SourceLocation& where, double seconds) override;
    void command(const MachineCommand& command) override;

    // ---- time (driven by the station)
    /// True while the look-ahead queue has room for the next block's outputs.
    bool wantsMore() const { return engine_.wantsMore(); }
    /// Batching (docs/decisions/motion.md MOT-022), for a driver that gives
    /// the machine all the time it asks for in one advance() (the CLI
    /// without samples, no operator): the queue takes `entries` beyond the
    /// look-ahead depth, so the interpreter runs a batch of blocks and the
    /// machine works them off in one go. Positions, times, the trend clock
    /// and every signal come out as without a batch. 0: no batch.
    void setBatch(std::size_t entries);
    /// The station begins a block (before the interpreter's step).
    void beginBlock();
    /// Moves on by at most `seconds` of simulated time; returns the time
    /// used (less when the queue got room or ran empty first).
    double advance(double seconds);
    /// Nothing queued: the axes stand.
    bool idle() const { return engine_.idle(); }
    /// Feed hold (Stop): the axes brake on the path; resume() continues mid-block.
    void hold() { engine_.hold(); }
    void resume() { engine_.resume(); }
    bool held() const { return engine_.held(); }
    /// Single block: rest at the end of each block, wait for Start there.
    void setStopAtBlockEnds(bool on) { engine_.setStopAtBlockEnds(on); }
    bool atBlockStop() const { return engine_.atBlockStop(); }
    std::uint64_t itemsQueued() const { return engine_.itemsQueued(); }
    std::uint64_t itemsDone() const { return engine_.itemsDone(); }
    void continueAfterBlockStop() { engine_.continueAfterBlockStop(); }
    /// Control reset: the axes stop at once, the queue is emptied (queued
    /// auxiliary functions never reach the SPS); positions stay.
    void stop();
    /// Drops the queue once the axes are at rest, the spindles keep turning
    /// (a jog key released); false while the axes still move.
    bool discardAtRest();
    /// Feed override in percent of the programmed feed (0 ... feedOverrideMax()).
    void setFeedOverride(double percent) { engine_.setFeedOverride(percent); }
    double feedOverride() const { return engine_.feedOverride(); }
    /// Largest feed override of the process (B074, MOT-006).
    double feedOverrideMax() const { return engine_.limits().feedOverrideMax; }
    /// Rapid override in percent of the rapid velocity (0 ... 100).
    void setRapidOverride(double percent) { engine_.setRapidOverride(percent); }
    double rapidOverride() const { return engine_.rapidOverride(); }
    /// Busy simulated seconds since construction or the last reset().
    double seconds() const { return engine_.busySeconds(); }
    /// Position of machine axis `index` (order of ProcessConfig::axes), now.
    double position(int index) const { return engine_.position(index); }
    /// Distance machine axis `index` still has to go in the current move.
    double distanceToGo(int index) const { return engine_.distanceToGo(index); }
    /// Path feed the axes move at now, mm/min (0 standing, dwelling or held).
    double actualFeed() const { return engine_.velocity() * 60.0; }
    /// Program, block and line of the output being worked off (the last one
    /// when idle; empty before the first).
    SourceLocation currentLocation() const { return engine_.currentLocation(); }
    /// The spindles S1..S3 (actual speeds ramp in time).
    const motion::SpindleSet& spindles() const { return engine_.spindles(); }
    /// Spindle `spindle` (1..3) is configured (in spindle mode).
    bool hasSpindle(int spindle) const {
        return spindle >= 1 && spindle <= 3 &&
               engine_.limits().spindles[static_cast<std::size_t>(spindle)].present;
    }
    /// The trajectory engine (its queue, for views and tests).
    const motion::TrajectoryEngine& engine() const { return engine_; }
    std::uint64_t motionCount() const { return motions_; }
    /// The auxiliary functions the machine has reached (sent to the SPS),
    /// oldest first (last 200 kept).
    const std::vector<AuxOutput>& recentAux() const { return aux_; }
    /// Clears the clock, the output log and the attached trend recorder;
    /// positions stay where they are.
    void reset();

    /// Adaptive feed control of this process (not owned; nullptr = none):
    /// while it is available (Bxx.062) the machine runs ITM and the I
    /// controller of G26 over the feed moves and fills `recorder` (may be null).
    void attachAdaptiveFeed(AdaptiveFeedControl* afc, AfcTrendRecorder* recorder);
    /// Mean path feed of the last move, mm/min (after adaptive feed control).
    double lastMoveFeed() const { return lastFeed_.value(); }
    /// The last move was slowed down by G26.
    bool lastMoveAdapted() const { return lastAdapted_; }
    /// Share of the last move's path the axes travel (< 1: an error of
    /// adaptive feed control stops them at lastMoveEnd()).
    double lastMoveFraction() const { return lastFraction_; }
    /// Where the axes stand after the last queued move (its end, or where
    /// adaptive feed control stopped it), machine positions.
    const std::array<double, kMaxAxes>& lastMoveEnd() const { return lastEnd_; }
    /// The last move ran with G26 on or with an idle torque measurement
    /// (ITM) requested: its feed is the one adaptive feed control gave.
    bool lastMoveReportsAfc() const { return lastReportsAfc_; }

  private:
    /// After the queue was dropped: the queued ends and aux functions go.
    void standWhereStopped();
    /// G26 / ITM: the move is worked out by adaptive feed control now and
    /// queued as a timed move.
    void adaptiveMove(const Motion& motion, double planned, double length);
    /// G25: the torque is only observed, for the trend recorder; without
    /// one only the trend clock and the feed follow the move.
    void observeMove(const Motion& motion, double planned, double length);
    /// What adaptive feed control needs of the move; `length`: its path
    /// length (mm). The acceleration time only matters to ITM (adaptive moves).
    AfcMoveInput afcInput(const Motion& motion, double planned, double length) const;
    /// The override of the move's kind in force, as a share (1 below 1 %).
    double overrideShare(const Motion& motion) const;
    /// `length`: the move's path length (mm), known to the caller.
    double referenceSpeedFraction(const Motion& motion, double pathFeed, double length) const;
    double accelerationSeconds(const Motion& motion, double feed) const;
    /// Moves the auxiliary functions the engine reached into recentAux().
    void collectReached() {
        if (engine_.reachedActions()) moveReachedAux();  // nearly always none
    }
    void moveReachedAux();
    /// Trend clock: the queued work ends `seconds` later, counted from the
    /// end of what was queued or from the machine's busy time when the block
    /// was queued, whichever is later. Under a batch it is counted once the
    /// machine is where it would stand without the batch (MOT-022).
    void queueClock(double seconds);
    void stepClock(double seconds, double busy);
    /// The clock steps whose moment the machine has reached, at its busy time now.
    void applyClockSteps();
    /// The same after advance() let the engine run on from `doneBefore`
    /// items done: each step at the busy time the machine had when it was
    /// due (finishedAt_).
    void applyClockStepsAfter(std::uint64_t doneBefore);
    void dropTakenClockSteps();
    /// Batching: works the queue off to where the machine would stand now
    /// without a batch (before anything reads the machine's time).
    void catchUp();

    const ProcessConfig& config_;
    motion::TrajectoryEngine engine_;
    AdaptiveFeedControl* afc_ = nullptr;
    AfcTrendRecorder* recorder_ = nullptr;
    std::unique_ptr<AfcMaterial> material_;  ///< where the raw part is (engagement)
    std::array<double, 4> spindleSpeed_{};   ///< last S per spindle 1..3 (rpm), as queued
    /// Trend clock: where the queued work ends at the programmed feeds
    /// (start of the next observed move; adaptive moves start at the exact
    /// end of the queue).
    double afcClock_ = 0.0;
    /// Mean path feed of the last move: a ratio is divided out when it is
    /// read (the CLI without motion output never reads it, MOT-026), with
    /// the same operations as when it was worked out on every move.
    struct MoveFeed {
        double feed = 0.0;  ///< the feed itself when not `ratio`
        double length = 0.0, seconds = 0.0;
        bool ratio = false;  ///< length / seconds * 60
        double value() const { return ratio ? length / seconds * 60.0 : feed; }
    };
    MoveFeed lastFeed_;
    bool lastAdapted_ = false;
    double lastFraction_ = 1.0;
    bool lastReportsAfc_ = false;
    std::array<double, kMaxAxes> lastEnd_{};
    std::uint64_t motions_ = 0;
    std::uint32_t nextTag_ = 0;         ///< tag of the last queued auxiliary function
    std::deque<AuxOutput> pendingAux_;  ///< queued, not yet reached (tags in order)
    std::vector<AuxOutput> aux_;
    /// Batching: a clock step waiting for the machine to have done `itemsDone` items.
    struct ClockStep {
        std::uint64_t itemsDone = 0;
        double seconds = 0.0;
    };
    std::vector<ClockStep> clockSteps_;  ///< in queue order, from clockStepsDone_ on
    std::size_t clockStepsDone_ = 0;
    /// The busy time at the end of each entry the last advance() finished.
    std::vector<double> finishedAt_;
    /// Batching: itemsDone() when the block being interpreted would have been
    /// queued without a batch (0 without a batch: now).
    std::uint64_t blockDue_ = 0;
};

}  // namespace mtc::core
