#include "cnc_core/machine/AxisTransfer.h"

#include <algorithm>
#include <cctype>

namespace mtc::core {

AxisTransfer::Ticket AxisTransfer::post(int process, AxisTransferKind kind,
                                        const std::string& axis) {
    std::lock_guard<std::mutex> lock(mutex_);
    return postLocked(process, kind, axis, false);
}

AxisTransfer::Ticket AxisTransfer::postLocked(int process, AxisTransferKind kind,
                                              const std::string& axis, bool standing) {
    const Ticket ticket = next_++;
    const auto partner = std::find_if(open_.begin(), open_.end(), [&](const Request& r) {
        return r.process != process && r.kind != kind && r.axis == axis;
    });
    if (partner != open_.end()) {
        // Both requests are done; the process of the GAX holds the axis now.
        setHolderLocked(axis, kind == AxisTransferKind::Get ? process : partner->process);
        open_.erase(partner);
        return ticket;
    }
    open_.push_back({ticket, process, kind, axis, standing});
    return ticket;
}

void AxisTransfer::setHolderLocked(const std::string& axis, int process) {
    holders_[axis] = process;
    revision_.fetch_add(1, std::memory_order_acq_rel);
}

int AxisTransfer::holder(const std::string& axis) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto found = holders_.find(axis);
    return found == holders_.end() ? kAtHome : found->second;
}

AxisTransfer::Ticket AxisTransfer::request(int process, const std::string& axis) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto freeOf = [&](bool own) {
        return std::find_if(open_.begin(), open_.end(), [&](const Request& r) {
            return r.kind == AxisTransferKind::Free && r.axis == axis &&
                   (r.process == process) == own;
        });
    };
    if (freeOf(false) != open_.end()) {
        const Ticket ticket = postLocked(process, AxisTransferKind::Get, axis, false);
        (void)ticket;  // met the released axis at once
        return 0;
    }
    const auto own = freeOf(true);
    if (own != open_.end()) {  // released it itself, nobody took it: back again
        open_.erase(own);
        setHolderLocked(axis, process);
        return 0;
    }
    const auto found = holders_.find(axis);
    if (found == holders_.end() || found->second == process) {
        setHolderLocked(axis, process);
        return 0;
    }
    return postLocked(process, AxisTransferKind::Get, axis, false);
}

bool AxisTransfer::release(int process, const std::string& axis) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto found = holders_.find(axis);
    const int holder = found == holders_.end() ? kAtHome : found->second;
    if (holder == kNobody)  // released already: by this process it is a repeat
        return std::any_of(open_.begin(), open_.end(), [&](const Request& r) {
            return r.standing && r.process == process && r.axis == axis;
        });
    if (holder != process && holder != kAtHome) return false;
    setHolderLocked(axis, kNobody);
    postLocked(process, AxisTransferKind::Free, axis, true);
    return true;
}

bool AxisTransfer::done(Ticket ticket) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::none_of(open_.begin(), open_.end(),
                        [ticket](const Request& r) { return r.ticket == ticket; });
}

void AxisTransfer::cancel(int process) {
    std::lock_guard<std::mutex> lock(mutex_);
    open_.erase(
        std::remove_if(open_.begin(), open_.end(),
                       [process](const Request& r) { return r.process == process && !r.standing; }),
        open_.end());
}

std::vector<AxisTransfer::Request> AxisTransfer::open() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return open_;
}

}  // namespace mtc::core
