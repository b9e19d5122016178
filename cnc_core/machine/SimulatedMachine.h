#pragma once

#include <cstdint>
#include <vector>

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/MachineConfig.h"

namespace mtc::core {

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
    /// Clears the clock and the output log; positions stay where they are.
    void reset();

  private:
    const ProcessConfig& config_;
    std::array<double, kMaxAxes> position_{};
    double seconds_ = 0.0;
    std::uint64_t motions_ = 0;
    std::vector<AuxOutput> aux_;
};

}  // namespace mtc::core
