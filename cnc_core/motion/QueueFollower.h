#pragma once

#include <optional>

#include "cnc_core/motion/TrajectoryEngine.h"

namespace mtc::core::motion {

/// One rule for everything that follows the machine's queue from outside
/// (the run's trace, the live cut): the machine works its queue off in
/// order, so of `pending` (what the observer handed to the machine, oldest
/// first, one entry per queued move) the entries beyond what the machine
/// still holds are finished. `finished(entry)` is called for each of them,
/// oldest first, before it is dropped. Returns the share of the front
/// entry's move the axes have travelled, or nothing when no entry is in
/// motion (none pending, or the axes stand).
template <class Queue, class Finished>
std::optional<double> followMachineQueue(const TrajectoryEngine& engine, Queue& pending,
                                         Finished&& finished) {
    const auto inQueue = engine.queuedMoves();
    while (pending.size() > inQueue) {
        finished(pending.front());
        pending.pop_front();
    }
    if (pending.empty() || engine.currentMove() == nullptr) return std::nullopt;
    return engine.travelledShare();
}

}  // namespace mtc::core::motion
