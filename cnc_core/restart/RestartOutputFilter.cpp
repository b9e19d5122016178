#include "cnc_core/restart/RestartOutputFilter.h"

namespace mtc::core {

void RestartOutputFilter::command(const MachineCommand& command) {
    if (!performedWhileComputing(command)) {
        ++suppressed_;
        return;
    }
    ++passed_;
    sps_.command(command);
    const auto* transfer = std::get_if<AxisTransferCommand>(&command.action);
    if (!transfer_ || !transfer) return;
    for (const std::string& axis : transfer->axes) {
        const AxisTransfer::Ticket ticket = transfer_->post(process_, transfer->kind, axis);
        if (!transfer_->done(ticket))
            pending_.push_back({ticket, std::string(keywordName(command.keyword)) + " " + axis});
    }
    if (!pending_.empty() && hold_) hold_();
}

void RestartOutputFilter::setAxisTransfer(AxisTransfer* transfer, int process,
                                          std::function<void()> hold) {
    cancelTransfers();
    transfer_ = transfer;
    process_ = process;
    hold_ = std::move(hold);
}

bool RestartOutputFilter::waiting() const {
    for (const Pending& p : pending_)
        if (!transfer_->done(p.ticket)) return true;
    return false;
}

std::string RestartOutputFilter::waitingFor() const {
    for (const Pending& p : pending_)
        if (!transfer_->done(p.ticket)) return p.text;
    return {};
}

void RestartOutputFilter::cancelTransfers() {
    if (transfer_ && !pending_.empty()) transfer_->cancel(process_);
    pending_.clear();
}

}  // namespace mtc::core
