#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mtc::core {

/// One point of the adaptive feed trend (seed 002 Fig. 2-1): the actual and
/// machining torque of the reference axis, the limits in force at that
/// moment and the feed reduction. Torques in % of the nominal drive torque.
struct AfcTrendSample {
    double time = 0.0;               ///< simulated machine time, s
    double torqueActual = 0.0;       ///< S-0-0084
    double machiningTorque = 0.0;    ///< 007 (also computed while G25)
    double idleTorque = 0.0;         ///< 005
    double limitingTorque = 0.0;     ///< 010 / Bxx.064
    double minimumTorque = 0.0;      ///< 009 / Bxx.065
    double maximumIdleTorque = 0.0;  ///< 006 / Bxx.066
    double feedReduction = 0.0;      ///< 011, %
    double peakReduction = 0.0;      ///< highest 011 since G26, %
    double maximumReduction = 0.0;   ///< 013 / Bxx.067, %
    double effectiveFeed = 0.0;      ///< mm/min the axes get
    double stallTorque = 0.0;        ///< 014
    bool active = false;             ///< G26 in force
    bool measuringIdle = false;      ///< inside the measuring period of ITM
    bool excessiveThrust = false;    ///< PxxS.EXCTH
    bool thrustMissing = false;      ///< PxxS.THMIS
};

/// Bounded ring buffer of trend samples, filled by the simulated machine
/// while feed moves run: the oldest sample is dropped when it is full.
/// Plain data; the trend screen reads it by index.
class AfcTrendRecorder {
  public:
    /// Keeps at most `capacity` samples (at least 2).
    explicit AfcTrendRecorder(std::size_t capacity = 20000);

    /// Appends a sample (drops the oldest when full).
    void add(const AfcTrendSample& sample);
    /// Number of samples kept.
    std::size_t size() const { return count_; }
    std::size_t capacity() const { return buffer_.size(); }
    /// Sample `index`, 0 = the oldest kept.
    const AfcTrendSample& at(std::size_t index) const;
    /// Every kept sample, oldest first.
    std::vector<AfcTrendSample> samples() const;
    /// Counts every add() and clear() (screens repaint when it moves).
    std::uint64_t revision() const { return revision_; }
    /// Forgets every sample.
    void clear();
    /// The samples as CSV with a header line (C locale numbers, '.' decimal).
    std::string csv() const;

  private:
    std::vector<AfcTrendSample> buffer_;
    std::size_t first_ = 0;
    std::size_t count_ = 0;
    std::uint64_t revision_ = 0;
};

}  // namespace mtc::core
