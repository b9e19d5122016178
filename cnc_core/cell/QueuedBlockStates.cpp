#include "cnc_core/cell/QueuedBlockStates.h"

namespace mtc::core {

QueuedBlockState& QueuedBlockStates::record() {
    if (states_.size() >= kCapacity) {
        states_.pop_front();
        matched_ = false;
    }
    return states_.emplace_back();
}

void QueuedBlockStates::follow(const SourceLocation& at, bool idle) {
    matched_ = false;
    if (idle) {
        states_.clear();
        return;
    }
    for (std::size_t i = 0; i < states_.size(); ++i) {
        if (states_[i].program != at.program || states_[i].line != at.line) continue;
        // A loop queues the same line more than once: the oldest entry is
        // the one executed, the machine works the queue in order.
        states_.dropFront(i);
        matched_ = true;
        return;
    }
}

const QueuedBlockState* QueuedBlockStates::executing() const {
    return matched_ && !states_.empty() ? &states_.front() : nullptr;
}

void QueuedBlockStates::clear() {
    states_.clear();
    matched_ = false;
}

}  // namespace mtc::core
