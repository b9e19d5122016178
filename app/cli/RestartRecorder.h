#pragma once

#include <string>
#include <vector>

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/restart/RestartSequence.h"

namespace mtc::cli {

/// What `restart` reports of the machine side: every auxiliary function that
/// reached the SPS (during the computing process only those the process
/// parameters Bxx.058..061 let through), tagged with the restart phase it
/// happened in, and the moves of ADJUST and of REPOS.
class RestartRecorder : public core::MachineSink {
  public:
    struct Aux {
        core::AuxOutput output;
        std::string phase;  ///< "computing", "adjust", "repos", ...
    };

    /// The sequence whose phase tags the records (not owned; may be null).
    void setSequence(const core::RestartSequence* sequence) { sequence_ = sequence; }

    /// Keeps a move of ADJUST or REPOS (others, e.g. jogs, are not reported).
    void motion(const core::Motion& motion) override;
    /// Keeps every auxiliary function with the phase it came in.
    void auxiliary(const core::AuxOutput& output) override;
    void dwell(const core::SourceLocation&, double) override {}
    void command(const core::MachineCommand&) override { ++commands_; }

    /// What was recorded, in order.
    const std::vector<Aux>& aux() const { return aux_; }
    const std::vector<core::Motion>& adjustMotion() const { return adjustMotion_; }
    const std::vector<core::Motion>& reposMotion() const { return reposMotion_; }
    std::uint64_t commandCount() const { return commands_; }

  private:
    std::string phaseName() const;

    const core::RestartSequence* sequence_ = nullptr;
    std::vector<Aux> aux_;
    std::vector<core::Motion> adjustMotion_;
    std::vector<core::Motion> reposMotion_;
    std::uint64_t commands_ = 0;
};

}  // namespace mtc::cli
