#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/MachineConfig.h"

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

/// The machine behind a station's interpreter (cnc_core/cell/Station): it
/// takes every output into a bounded queue and works it off in simulated
/// time when the station calls advance(). The contract the station relies on
/// (TEAM.md, station <-> motion-tools):
///  - the interpreter may send the next block while wantsMore() is true; a
///    block's outputs are always taken, even when they overfill the queue;
///  - advance(dt) moves on by at most dt and returns the time it used; it
///    returns early the moment the queue has room again or runs empty, so
///    the station refills it at exactly that simulated instant. The result
///    must not depend on how the time is cut into advance() calls (the CLI
///    advances in one call what the panel does in 20 ms ticks);
///  - seconds() counts only busy time (moving, dwelling): a program takes
///    the same simulated time whether the operator waits at M00 or not;
///  - hold() / resume() is feed hold, stop() (Control reset) empties the
///    queue at once, positions stay where the axes are.
/// Interim implementation until the time-based engine (cnc_core/motion)
/// replaces it: a queue of one output, the axes jump to the end point when a
/// move is queued and the move then takes its duration (motionSeconds(), at
/// the override) before the next one is taken.
class SimulatedMachine : public MachineSink {
  public:
    explicit SimulatedMachine(const ProcessConfig& config);
    ~SimulatedMachine() override;
    SimulatedMachine(const SimulatedMachine&) = delete;
    SimulatedMachine& operator=(const SimulatedMachine&) = delete;

    void motion(const Motion& motion) override;
    void auxiliary(const AuxOutput& output) override;
    void dwell(const SourceLocation& where, double seconds) override;
    void command(const SourceLocation& where, const std::string& keyword,
                 const std::string& arguments) override;

    // ---- time (driven by the station)
    /// True while the queue has room for the next block's outputs.
    bool wantsMore() const { return idle(); }
    /// Moves on by at most `seconds` of simulated time; returns the time
    /// used (less when the queue got room or ran empty first).
    double advance(double seconds);
    /// Nothing queued: the axes stand.
    bool idle() const { return remaining_ <= 0.0; }
    /// Feed hold (Stop): the queued work waits; resume() continues it.
    void hold() { held_ = true; }
    void resume() { held_ = false; }
    bool held() const { return held_; }
    /// Control reset: the queue is emptied at once; positions stay.
    void stop();
    /// Feed override in percent of the programmed feed (0 ... configured maximum).
    void setFeedOverride(double percent) { feedOverride_ = percent < 0 ? 0.0 : percent; }
    double feedOverride() const { return feedOverride_; }
    /// Rapid override in percent of the rapid velocity.
    void setRapidOverride(double percent) { rapidOverride_ = percent < 0 ? 0.0 : percent; }
    double rapidOverride() const { return rapidOverride_; }
    /// Busy simulated seconds since construction or the last reset().
    double seconds() const { return seconds_; }
    /// Position of machine axis `index` (order of ProcessConfig::axes).
    double position(int index) const;
    /// Distance machine axis `index` still has to go in the current move.
    double distanceToGo(int index) const;
    /// Path feed the axes move at now, mm/min (0 standing, dwelling or held).
    double actualFeed() const;
    /// Program, block and line of the output being worked off (the last one
    /// when idle; empty before the first).
    const SourceLocation& currentLocation() const { return current_; }
    std::uint64_t motionCount() const { return motions_; }
    /// The auxiliary functions sent to the SPS, oldest first (last 200 kept).
    const std::vector<AuxOutput>& recentAux() const { return aux_; }
    /// Clears the clock, the output log and the attached trend recorder;
    /// positions stay where they are.
    void reset();

    /// Adaptive feed control of this process (not owned; nullptr = none):
    /// while it is available (Bxx.062) the machine runs ITM and the I
    /// controller of G26 over the feed moves and fills `recorder` (may be null).
    void attachAdaptiveFeed(AdaptiveFeedControl* afc, AfcTrendRecorder* recorder);
    /// Mean path feed of the last move, mm/min (after adaptive feed control).
    double lastMoveFeed() const { return lastFeed_; }
    /// The last move was slowed down by G26.
    bool lastMoveAdapted() const { return lastAdapted_; }
    /// Share of the last move's path the axes travelled (< 1: an error of
    /// adaptive feed control stopped them; position() says where).
    double lastMoveFraction() const { return lastFraction_; }
    /// The last move ran with G26 on or with an idle torque measurement
    /// (ITM) requested: its feed is the one adaptive feed control gave.
    bool lastMoveReportsAfc() const { return lastReportsAfc_; }

  private:
    /// The move under adaptive feed control; returns its duration and
    /// sets the positions (short of the end when an error stopped it).
    double adaptiveMove(const Motion& motion, double planned);
    double referenceSpeedFraction(const Motion& motion) const;
    double accelerationSeconds(const Motion& motion, double feed) const;

    const ProcessConfig& config_;
    AdaptiveFeedControl* afc_ = nullptr;
    AfcTrendRecorder* recorder_ = nullptr;
    std::unique_ptr<AfcMaterial> material_;  ///< where the raw part is (engagement)
    std::array<double, 4> spindleSpeed_{};   ///< last S per spindle 1..3 (rpm)
    double lastFeed_ = 0.0;
    bool lastAdapted_ = false;
    double lastFraction_ = 1.0;
    bool lastReportsAfc_ = false;
    std::array<double, kMaxAxes> position_{};
    double seconds_ = 0.0;
    double remaining_ = 0.0;  ///< work of the queued output, seconds at 100 %
    bool remainingIsRapid_ = false;
    bool remainingIsDwell_ = false;
    bool held_ = false;
    double feedOverride_ = 100.0;
    double rapidOverride_ = 100.0;
    SourceLocation current_;
    std::uint64_t motions_ = 0;
    std::vector<AuxOutput> aux_;
};

}  // namespace mtc::core
