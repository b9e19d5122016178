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

/// The machine behind the panel's interpreter: it takes every output,
/// keeps the position of each axis, and advances a simulated clock by the
/// time each move and dwell takes. The panel's simulation clock executes
/// blocks until this clock has caught up with real time × speed.
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

    /// Simulated seconds since construction or the last reset().
    double seconds() const { return seconds_; }
    /// Position of machine axis `index` (order of ProcessConfig::axes).
    double position(int index) const;
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
    std::array<double, kMaxAxes> position_{};
    double seconds_ = 0.0;
    std::uint64_t motions_ = 0;
    std::vector<AuxOutput> aux_;
};

}  // namespace mtc::core
