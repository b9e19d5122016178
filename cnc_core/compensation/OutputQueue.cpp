#include "cnc_core/compensation/OutputQueue.h"

namespace mtc::core {

OutputQueue::Item& OutputQueue::push(Kind kind) {
    if (used_ == items_.size()) items_.emplace_back();
    Item& item = items_[used_++];
    item.kind = kind;
    return item;
}

void OutputQueue::release(const std::function<void(Motion&)>& adjust) {
    holding_ = false;
    // Items are sent by index: a sink that calls back into the interpreter
    // cannot add to the queue while it is not holding.
    for (std::size_t i = 0; i < used_; ++i) {
        Item& item = items_[i];
        switch (item.kind) {
            case Kind::Motion:
                adjust(item.motion);
                downstream_.motion(item.motion);
                break;
            case Kind::Auxiliary:
                downstream_.auxiliary(item.aux);
                break;
            case Kind::Dwell:
                downstream_.dwell(item.where, item.seconds);
                break;
            case Kind::Command:
                downstream_.command(item.command);
                break;
        }
    }
    used_ = 0;
}

void OutputQueue::clear() {
    holding_ = false;
    used_ = 0;
}

void OutputQueue::queueMotion(const Motion& motion) {
    push(Kind::Motion).motion = motion;
}

void OutputQueue::auxiliary(const AuxOutput& output) {
    if (!holding_) return downstream_.auxiliary(output);
    push(Kind::Auxiliary).aux = output;
}

void OutputQueue::dwell(const SourceLocation& where, double seconds) {
    if (!holding_) return downstream_.dwell(where, seconds);
    Item& item = push(Kind::Dwell);
    item.where = where;
    item.seconds = seconds;
}

void OutputQueue::command(const MachineCommand& command) {
    if (!holding_) return downstream_.command(command);
    push(Kind::Command).command = command;
}

}  // namespace mtc::core
