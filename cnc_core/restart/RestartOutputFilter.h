#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/AxisTransfer.h"

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
/// and AXD pass like in normal operation. With an AxisTransfer attached, GAX
/// and FAX also post their request there and ask for a hold after the block
/// until another process answers (seed 000, 5.4; R-021).
class RestartOutputFilter : public MachineSink {
  public:
    /// `sps` receives what passes (not owned).
    explicit RestartOutputFilter(MachineSink& sps) : sps_(sps) {}

    /// Motion and dwells are dropped (the computing process moves nothing).
    void motion(const Motion&) override {}
    void dwell(const SourceLocation&, double) override {}
    /// Auxiliary functions the interpreter forwards go to the SPS.
    void auxiliary(const AuxOutput& output) override { sps_.auxiliary(output); }
    /// Passes the command to the SPS unless the computing process does not
    /// perform it (performedWhileComputing()).
    void command(const MachineCommand& command) override;

    /// Commands held back since construction or resetCounters().
    std::uint64_t suppressedCount() const { return suppressed_; }
    std::uint64_t passedCount() const { return passed_; }
    void resetCounters() { suppressed_ = passed_ = 0; }

    /// The cell's axis transfer handshake for process `process` (nullptr: GAX
    /// and FAX do not wait, e.g. a process alone in the CLI). `hold` is called
    /// when a block posted a request that has not met its partner yet.
    void setAxisTransfer(AxisTransfer* transfer, int process, std::function<void()> hold);
    /// A GAX / FAX of this process waits for its partner.
    bool waiting() const;
    /// "GAX X1" of the first request that still waits ("" when none).
    std::string waitingFor() const;
    /// Withdraws the waiting requests (abort, Control reset, a new begin()).
    void cancelTransfers();

  private:
    MachineSink& sps_;
    std::uint64_t suppressed_ = 0;
    std::uint64_t passed_ = 0;
    struct Pending {
        AxisTransfer::Ticket ticket;
        std::string text;  ///< "GAX X1"
    };
    AxisTransfer* transfer_ = nullptr;
    int process_ = 0;
    std::function<void()> hold_;
    std::vector<Pending> pending_;
};

}  // namespace mtc::core
