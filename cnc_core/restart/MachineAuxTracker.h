#pragma once

#include "cnc_core/interp/AuxFunctionGroups.h"
#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/restart/RestartStateCompare.h"

namespace mtc::core {

/// Stands in front of the machine and keeps what the machine itself
/// executed of the aux functions it received: the last M of each group 1..15
/// (by the interpreter's group rule) and the speed of each spindle. While
/// `executing` is off (the computing process: the SPS only collects what it
/// gets, seed 000, 3.1) it forwards without keeping. Everything is forwarded
/// to `next` when one is given.
class MachineAuxTracker : public MachineSink {
  public:
    explicit MachineAuxTracker(const ProcessConfig& config, MachineSink* next = nullptr)
        : groups_(config), next_(next) {}

    /// The machine as the NC's memory `state` says (normal operation up to now).
    void reset(const InterpreterState& state) {
        machine_.mGroups = state.mGroups;
        machine_.spindleSpeed = state.modal.spindleSpeed;
    }
    void setExecuting(bool executing) { executing_ = executing; }
    const MachineAuxState& state() const { return machine_; }

    void motion(const Motion& m) override {
        if (next_) next_->motion(m);
    }
    void auxiliary(const AuxOutput& a) override {
        if (executing_) keep(a);
        if (next_) next_->auxiliary(a);
    }
    void dwell(const SourceLocation& where, double seconds) override {
        if (next_) next_->dwell(where, seconds);
    }
    void command(const MachineCommand& command) override {
        if (next_) next_->command(command);
    }

  private:
    void keep(const AuxOutput& a) {
        if (a.type == 'M') {
            const int m = static_cast<int>(a.value);
            const int group = groups_.groupOf(m);
            if (group >= 1 && group <= 15) machine_.mGroups[static_cast<std::size_t>(group)] = m;
        } else if (a.type == 'S' && a.spindle >= 1 && a.spindle < kSpindleSlots) {
            machine_.spindleSpeed[static_cast<std::size_t>(a.spindle)] = a.value;
        }
    }

    AuxFunctionGroups groups_;
    MachineSink* next_;
    MachineAuxState machine_;
    bool executing_ = true;
};

}  // namespace mtc::core
