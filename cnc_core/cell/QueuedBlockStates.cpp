#include "cnc_core/cell/QueuedBlockStates.h"

namespace mtc::core {

QueuedBlockState& QueuedBlockStates::record() {
    if (states_.size() >= kCapacity) {
        states_.pop_front();
        matched_ = false;
    }
    return states_.emplace_back();
}

void QueuedBlockStates::follow(std::uint64_t itemsDone, bool atBlockStop, bool idle) {
    matched_ = false;
    if (idle) {
        clear();
        return;
    }
    // The item the axes work on; at a single-block stop the one they finished.
    const std::uint64_t current = atBlockStop && itemsDone > 0 ? itemsDone - 1 : itemsDone;
    std::size_t done = 0;
    while (done < states_.size() && states_[done].endItem <= current)
        ++done;
    states_.dropFront(done);
    // Not one of the recorded blocks when the item lies before the front
    // entry's (a restart's move, a jog).
    matched_ = !states_.empty() && states_.front().firstItem <= current;
}

const QueuedBlockState* QueuedBlockStates::executing() const {
    return matched_ && !states_.empty() ? &states_.front() : nullptr;
}

void QueuedBlockStates::clear() {
    if (states_.capacity() > 0) states_ = {};  // lets go of the programs of every slot
    matched_ = false;
}

}  // namespace mtc::core
