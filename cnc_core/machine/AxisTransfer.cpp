#include "cnc_core/machine/AxisTransfer.h"

#include <algorithm>
#include <cctype>

namespace mtc::core {

AxisTransfer::Ticket AxisTransfer::post(int process, AxisTransferKind kind,
                                        const std::string& axis) {
    std::lock_guard<std::mutex> lock(mutex_);
    const Ticket ticket = next_++;
    const auto partner = std::find_if(open_.begin(), open_.end(), [&](const Request& r) {
        return r.process != process && r.kind != kind && r.axis == axis;
    });
    if (partner != open_.end()) {
        open_.erase(partner);  // both requests are done
        return ticket;
    }
    open_.push_back({ticket, process, kind, axis});
    return ticket;
}

bool AxisTransfer::done(Ticket ticket) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::none_of(open_.begin(), open_.end(),
                        [ticket](const Request& r) { return r.ticket == ticket; });
}

void AxisTransfer::cancel(int process) {
    std::lock_guard<std::mutex> lock(mutex_);
    open_.erase(std::remove_if(open_.begin(), open_.end(),
                               [process](const Request& r) { return r.process == process; }),
                open_.end());
}

std::vector<AxisTransfer::Request> AxisTransfer::open() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return open_;
}

bool parseAxisTransfer(const std::string& keyword, const std::string& arguments,
                       AxisTransferKind& kind, std::vector<std::string>& axes) {
    if (keyword == "GAX")
        kind = AxisTransferKind::Get;
    else if (keyword == "FAX")
        kind = AxisTransferKind::Free;
    else
        return false;
    axes.clear();
    // The parser keeps the rest of the block as the command's arguments: the
    // axes are the list in the parentheses right after the keyword, or the
    // first word when there are none.
    const std::size_t first = arguments.find_first_not_of(" \t");
    if (first == std::string::npos) return false;
    std::string list;
    if (arguments[first] == '(') {
        const std::size_t close = arguments.find(')', first);
        list = arguments.substr(first + 1, close == std::string::npos ? close : close - first - 1);
    } else {
        list = arguments.substr(first, arguments.find_first_of(" \t", first) - first);
    }
    std::string name;
    for (char c : list + ",") {
        if (c == ',') {
            if (!name.empty()) axes.push_back(name);
            name.clear();
        } else if (!std::isspace(static_cast<unsigned char>(c))) {
            name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        }
    }
    return !axes.empty();
}

}  // namespace mtc::core
