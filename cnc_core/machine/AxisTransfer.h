#pragma once

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace mtc::core {

/// GAX / FAX of one process: request an axis or relinquish it.
enum class AxisTransferKind { Get, Free };

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
    /// process for the same axis at once, if there is one. Returns its ticket.
    Ticket post(int process, AxisTransferKind kind, const std::string& axis);
    /// True when the request `ticket` has met its partner (or is unknown:
    /// cancelled requests do not wait).
    bool done(Ticket ticket) const;
    /// Withdraws every open request of `process` (Control reset, abort).
    void cancel(int process);
    /// Open requests (for the screens: who waits for what).
    struct Request {
        Ticket ticket = 0;
        int process = 0;
        AxisTransferKind kind = AxisTransferKind::Get;
        std::string axis;
    };
    std::vector<Request> open() const;

  private:
    mutable std::mutex mutex_;
    std::vector<Request> open_;
    Ticket next_ = 1;
};

/// The axes of an axis transfer command: keyword "GAX" / "FAX" (else false)
/// and its arguments as the parser keeps them (the rest of the block):
/// "(X1)" or "(X1, Z2) AXD ..." give the list in the parentheses, "X1 ..."
/// the first word; names are upper case. False as well when no axis is named.
bool parseAxisTransfer(const std::string& keyword, const std::string& arguments,
                       AxisTransferKind& kind, std::vector<std::string>& axes);

}  // namespace mtc::core
