#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "cnc_core/interp/MachineCommand.h"  // AxisTransferKind

namespace mtc::core {

/// The handshake of the axis transfer commands between the processes of a
/// cell (seed 000, 5.4 "Axis transfer"): a process that relinquishes an axis
/// with FAX waits until another process requests it with GAX, and a process
/// that requests an axis with GAX waits until another process relinquishes it
/// with FAX. Each command posts a request; a Get and a Free of the same axis
/// from two different processes meet and both are done. One object per cell
/// (no globals); thread-safe, so processes may run on different threads.
class AxisTransfer {
  public:
    using Ticket = std::uint64_t;

    /// Posts GAX / FAX of `axis` (the name as programmed, e.g. "X1") by
    /// `process`. It meets the oldest open opposite request of another
    /// process for the same axis at once, if there is one; a met GAX makes
    /// its process the holder of the axis. Returns its ticket.
    Ticket post(int process, AxisTransferKind kind, const std::string& axis);

    /// Axis ownership of normal program runs (docs/decisions/restart.md
    /// An axis no GAX / FAX has named yet is held by every process
    /// that has it (as without transfers); once named it has one holder.
    static constexpr int kNobody = -1;  ///< released with FAX, not taken yet
    static constexpr int kAtHome = -2;  ///< never transferred
    /// Holder of `axis`: a process, kNobody or kAtHome.
    int holder(const std::string& axis) const;
    /// GAX of a normal run: granted at once (returns 0) when `process`
    /// holds the axis, the axis was never transferred, or the process
    /// released it itself and nobody took it; otherwise the GAX meets a
    /// released axis or waits for the holder's FAX (ticket to wait on).
    Ticket request(int process, const std::string& axis);
    /// FAX of a normal run: `process` gives the axis up without waiting; an
    /// open GAX of another process takes it at once. False (nothing
    /// changes) when another process holds the axis.
    bool release(int process, const std::string& axis);
    /// Counts every change of a holder (cheap check whether to look again).
    std::uint64_t revision() const { return revision_.load(std::memory_order_acquire); }
    /// True when the request `ticket` has met its partner (or is unknown:
    /// cancelled requests do not wait).
    bool done(Ticket ticket) const;
    /// Withdraws every open request of `process` (Control reset, abort)
    /// that it waits on; a normal run's FAX stays released.
    void cancel(int process);
    /// Open requests (for the screens: who waits for what).
    struct Request {
        Ticket ticket = 0;
        int process = 0;
        AxisTransferKind kind = AxisTransferKind::Get;
        std::string axis;
        bool standing = false;  ///< normal-run FAX: its process does not wait
    };
    std::vector<Request> open() const;

  private:
    Ticket postLocked(int process, AxisTransferKind kind, const std::string& axis, bool standing);
    void setHolderLocked(const std::string& axis, int process);

    mutable std::mutex mutex_;
    std::vector<Request> open_;
    std::map<std::string, int> holders_;  ///< transferred axes only
    std::atomic<std::uint64_t> revision_{0};
    Ticket next_ = 1;
};

}  // namespace mtc::core
