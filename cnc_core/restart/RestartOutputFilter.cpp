#include "cnc_core/restart/RestartOutputFilter.h"

#include <array>
#include <string_view>

namespace mtc::core {

bool RestartOutputFilter::suppressed(const std::string& keyword) {
    // MRV: the turning-centre example of seed 000, 7.2 writes it where MRY
    // (wait for the tool storage) is meant; the parser knows it as a command.
    static constexpr std::array<std::string_view, 15> kNotPerformed = {
        "PMP", "NMP", "TSE", "TPE", "MFP", "MHP", "MMP", "MOP",
        "MRF", "MTP", "MRY", "MRV", "TCH", "TMS", "TSM"};
    for (std::string_view k : kNotPerformed)
        if (keyword == k) return true;
    return false;
}

void RestartOutputFilter::command(const SourceLocation& where, const std::string& keyword,
                                  const std::string& arguments) {
    if (suppressed(keyword)) {
        ++suppressed_;
        return;
    }
    ++passed_;
    sps_.command(where, keyword, arguments);
    AxisTransferKind kind{};
    std::vector<std::string> axes;
    if (!transfer_ || !parseAxisTransfer(keyword, arguments, kind, axes)) return;
    for (const std::string& axis : axes) {
        const AxisTransfer::Ticket ticket = transfer_->post(process_, kind, axis);
        if (!transfer_->done(ticket)) pending_.push_back({ticket, keyword + " " + axis});
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
