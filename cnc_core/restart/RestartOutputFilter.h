#pragma once

#include <cstdint>
#include <string>

#include "cnc_core/interp/MachineSink.h"

namespace mtc::core {

/// The sink of the computing process (seed 000, 2.7 and 5.4): it hands the
/// SPS what reaches it in normal operation as well, and nothing that would
/// move or change the machine. Motion and dwells never pass (the interpreter
/// does not even produce them). Auxiliary functions pass as the interpreter
/// forwards them (process parameters Bxx.058..061). Commands pass, except:
///  - PMP, NMP (read the position of analog drives),
///  - TSE, TPE (check spindle 1 / magazine place 1),
///  - MFP, MHP, MMP, MOP, MRF, MTP (tool storage motion) and MRY (MRV),
///  - TCH, TMS, TSM (tool transfers: the interpreter remembers the tool in
///    the spindle, the current tools list is not changed).
/// GAX, FAX, the process commands (DP, SP, RP, AP, WP, LP, POK, WES, WER)
/// and AXD pass like in normal operation.
class RestartOutputFilter : public MachineSink {
  public:
    /// `sps` receives what passes (not owned).
    explicit RestartOutputFilter(MachineSink& sps) : sps_(sps) {}

    /// Motion and dwells are dropped (the computing process moves nothing).
    void motion(const Motion&) override {}
    void dwell(const SourceLocation&, double) override {}
    /// Auxiliary functions the interpreter forwards go to the SPS.
    void auxiliary(const AuxOutput& output) override { sps_.auxiliary(output); }
    /// Passes the command to the SPS unless suppressed() says otherwise.
    void command(const SourceLocation& where, const std::string& keyword,
                 const std::string& arguments) override;

    /// True for a command the computing process does not perform.
    static bool suppressed(const std::string& keyword);
    /// Commands held back since construction or resetCounters().
    std::uint64_t suppressedCount() const { return suppressed_; }
    std::uint64_t passedCount() const { return passed_; }
    void resetCounters() { suppressed_ = passed_ = 0; }

  private:
    MachineSink& sps_;
    std::uint64_t suppressed_ = 0;
    std::uint64_t passed_ = 0;
};

}  // namespace mtc::core
