#pragma once

#include <functional>
#include <string>
#include <vector>

#include "cnc_core/interp/MachineSink.h"

namespace mtc::core {

/// The interpreter's sink while tool radius compensation holds a move back:
/// outputs pass straight to the machine until a move is held, then they wait
/// here in order (S, T, M, dwells, commands and moves without motion in the
/// plane of the following blocks) and go out when the held move is released.
/// At most the look-ahead's few blocks wait; the queue keeps its capacity.
class OutputQueue : public MachineSink {
  public:
    explicit OutputQueue(MachineSink& downstream) : downstream_(downstream) {}

    /// From now on outputs wait (a move is held).
    void hold() { holding_ = true; }
    bool holding() const { return holding_; }
    /// Sends what waits, in order, and lets outputs pass again. Every waiting
    /// move goes through `adjust` first (it gets its plane position then).
    void release(const std::function<void(Motion&)>& adjust);
    /// Forgets what waits (control reset: the machine never got it).
    void clear();
    MachineSink& downstream() { return downstream_; }

    /// Inline: a move that passes is one virtual call of the downstream sink.
    void motion(const Motion& motion) override {
        if (!holding_) return downstream_.motion(motion);
        queueMotion(motion);
    }
    void auxiliary(const AuxOutput& output) override;
    void dwell(const SourceLocation& where, double seconds) override;
    void command(const MachineCommand& command) override;

  private:
    enum class Kind : unsigned char { Motion, Auxiliary, Dwell, Command };
    struct Item {
        Kind kind = Kind::Motion;
        Motion motion;
        AuxOutput aux;
        SourceLocation where;
        double seconds = 0.0;
        MachineCommand command;
    };
    Item& push(Kind kind);
    void queueMotion(const Motion& motion);

    MachineSink& downstream_;
    bool holding_ = false;
    std::vector<Item> items_;
    std::size_t used_ = 0;  ///< items_[0, used_) wait; the rest is kept capacity
};

}  // namespace mtc::core
