// The station's machine sink (Station::Output): what the interpreter sends
// goes to the machine, and to the backplot, the live cut and a listener.
#include "cnc_core/cell/Station.h"

namespace mtc::core {

namespace {
/// A move the backplot or the live cut follows: they are told whether the
/// machine queued it. Out of line, so that the CLI's path (no view follows
/// the moves) saves no registers for it on every move (MOT-028).
[[gnu::noinline]] void followedMotion(SimulatedMachine& machine, RunTrace* trace,
                                      removal::LiveCut* cut, const Motion& m) {
    const std::size_t queued = machine.engine().queuedCount();
    machine.motion(m);
    const bool isQueued = machine.engine().queuedCount() > queued;
    if (trace) trace->sent(m, isQueued);
    if (cut) cut->sent(m, isQueued);
}
}  // namespace

void Station::Output::sent(const SourceLocation& where) {
    ++outputs;
    last.program = where.program;
    last.line = where.line;
}

void Station::Output::motion(const Motion& m) {
    sent(m.where);
    if (trace || cut)
        followedMotion(machine, trace, cut, m);
    else
        machine.motion(m);  // the CLI: no view follows the moves
    if (listener) listener->motion(m);
}

void Station::Output::auxiliary(const AuxOutput& a) {
    sent(a.where);
    machine.auxiliary(a);
    if (listener) listener->auxiliary(a);
}

void Station::Output::dwell(const SourceLocation& where, double seconds) {
    sent(where);
    machine.dwell(where, seconds);
    if (listener) listener->dwell(where, seconds);
}

void Station::Output::command(const MachineCommand& command) {
    sent(command.where);
    machine.command(command);
    if (listener) listener->command(command);
}

}  // namespace mtc::core
