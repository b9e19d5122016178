#pragma once

#include <array>
#include <cstdint>

#include "cnc_core/interp/AuxFunctionGroups.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/restart/FunctionBuffer.h"

namespace mtc::core {

/// Watches every auxiliary function of the computing process (forwarded to
/// the SPS or not) and fills the two buffers of page 61 (seed 000, 3.1 / 4.2 /
/// 5.2): M functions of group 16 and Q functions, by the rule of
/// AuxFunctionGroups (the interpreter's own group rule): M19 forms and the
/// program control functions are never stored. The M groups 1..15, S, T and
/// E are collected by the interpreter itself.
class RestartAuxCollector : public AuxObserver {
  public:
    explicit RestartAuxCollector(const ProcessConfig& config);

    /// Counts `output`; stores an M of group 16 (not M19 family) or a Q.
    void auxiliary(const AuxOutput& output, bool forwarded) override;
    /// Empties both buffers and the counters (start of a computing process).
    void clear();
    /// Sets both buffers (a computing process goes on from a checkpoint).
    void restore(const FunctionBuffer& m16, const FunctionBuffer& q) {
        m16_ = m16;
        q_ = q;
    }

    /// The M(16) buffer (page 61, sub 1) and the Q buffer (sub 2).
    const FunctionBuffer& m16() const { return m16_; }
    const FunctionBuffer& q() const { return q_; }
    /// Functions seen / forwarded to the SPS since clear().
    std::uint64_t seen() const { return seen_; }
    std::uint64_t forwarded() const { return forwarded_; }

    /// True when M function `m` belongs in the M(16) buffer of this process
    /// (AuxFunctionGroups::storedInBuffer(); outside M0..M999 the group is 16).
    bool storesInM16(int m) const {
        if (m >= 0 && m < AuxFunctionGroups::kFunctions)
            return storedInM16_[static_cast<std::size_t>(m)];
        return AuxFunctionGroups::storedInBuffer(m, 16);
    }

  private:
    /// AuxFunctionGroups::storedInBuffer() of every M0..M999, worked out
    /// once: the collector sees every M of the computing process.
    std::array<bool, AuxFunctionGroups::kFunctions> storedInM16_{};
    FunctionBuffer m16_;
    FunctionBuffer q_;
    std::uint64_t seen_ = 0;
    std::uint64_t forwarded_ = 0;
};

}  // namespace mtc::core
