#pragma once

#include <array>
#include <cstdint>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/support/RingQueue.h"

namespace mtc::core {

/// The interpreter's state right after a block that gave the machine work.
/// The interpreter runs up to the look-ahead ahead of the axes, so what the
/// base screen shows of the block being executed (G functions, zero offset,
/// tool, spindle direction, call level) must come from here, not from the
/// interpreter's state now.
struct QueuedBlockState {
    ProgramPtr source;        ///< the program of the block
    std::uint32_t index = 0;  ///< its block index
    int callLevel = 0;        ///< 0 = main program
    /// The machine's queue items of the block: firstItem <= n < endItem in
    /// SimulatedMachine::itemsQueued() counting (none when equal). A loop
    /// queues the same line again; the items tell its passes apart.
    std::uint64_t firstItem = 0, endItem = 0;
    ModalState modal;
    std::array<int, 17> mGroups{};
};

/// The states of the blocks in the machine's queue, oldest first. The
/// station records one per block with outputs and follows the block the
/// machine executes; the entries before it are done and dropped.
class QueuedBlockStates {
  public:
    /// Most entries kept: far more than a look-ahead holds; beyond it the
    /// oldest go (a display falls back to the interpreter's state).
    static constexpr std::size_t kCapacity = 4096;

    /// Appends an entry for the next block with outputs and returns it to be
    /// filled (the oldest goes when the capacity is reached).
    QueuedBlockState& record();
    /// The machine has done `itemsDone` queue items (atBlockStop: it stands
    /// at the end of the last of them, which is shown; idle: it has nothing
    /// queued): drops the entries of blocks whose items are all done.
    void follow(std::uint64_t itemsDone, bool atBlockStop, bool idle);
    /// The state of the block the machine executes; nullptr when it is not
    /// one of the recorded blocks (idle, jogging, a restart's move).
    const QueuedBlockState* executing() const;
    void clear();
    std::size_t size() const { return states_.size(); }

  private:
    /// A dropped entry keeps even its program: the station records the
    /// next block over it and sets the program only when it differs, so a
    /// block costs no reference-count traffic (two atomic operations, about
    /// 2 % of a headless run); clear() lets go of every program.
    struct KeepEverything {
        void operator()(QueuedBlockState& /*state*/) const {}
    };
    RingQueue<QueuedBlockState, KeepEverything> states_;
    bool matched_ = false;  ///< the front is the block the machine executes
};

}  // namespace mtc::core
