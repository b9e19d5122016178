// Axis ownership of normal program runs: GAX requests an axis, FAX releases
// it, a move needs the axes it moves (docs/decisions/restart.md R-022, seed
// 000, 5.4 "Axis transfer": GAX / FAX work in the computing process "like in
// normal program operation"). Only with a cell's AxisTransfer attached.
#include <cctype>

#include "cnc_core/interp/Interpreter.h"

namespace mtc::core {

namespace {

std::string upper(std::string text) {
    for (char& c : text)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

}  // namespace

int Interpreter::transferAxisIndex(const std::string& name) const {
    for (int i = 0; i < axes_.count(); ++i) {
        const AxisModel& axis = axes_.axis(i);
        if (upper(axis.displayName()) == name || upper(axis.configName) == name ||
            (axis.designation2.valid() && upper(axis.designation2.toString()) == name))
            return i;
    }
    return -1;
}

std::uint32_t Interpreter::axesNotHeld() {
    const std::uint64_t revision = axisTransfer_->revision();
    if (revision == ownershipRevision_) return axesNotHeld_;
    ownershipRevision_ = revision;
    axesNotHeld_ = 0;
    for (int i = 0; i < axes_.count(); ++i) {
        const int holder = axisTransfer_->holder(upper(axes_.axis(i).displayName()));
        if (holder != AxisTransfer::kAtHome && holder != config_.index) axesNotHeld_ |= 1u << i;
    }
    return axesNotHeld_;
}

bool Interpreter::planAxisOwnership(const BlockContext& context) {
    const Program& program = context.program;
    for (int c = 0; c < input_.commandCount; ++c) {
        const Word& word = program.words[input_.commands[static_cast<size_t>(c)]];
        const std::optional<MachineCommand> command =
            readMachineCommand(program.text(word.text), program.text(word.args));
        const auto* transfer =
            command ? std::get_if<AxisTransferCommand>(&command->action) : nullptr;
        if (!transfer) continue;
        const std::string keyword(keywordName(command->keyword));
        const AxisTransferKind kind = transfer->kind;
        if (transfer->axes.empty())
            return context.error("AXIS_TRANSFER", keyword + " names no axis", word.column);
        for (const std::string& name : transfer->axes) {
            const int axis = transferAxisIndex(name);
            if (axis < 0)
                return context.error("AXIS_TRANSFER",
                                     keyword + "(" + name + "): process " +
                                         std::to_string(config_.index) + " has no axis " + name,
                                     word.column);
            const int holder = axisTransfer_->holder(upper(axes_.axis(axis).displayName()));
            if (kind == AxisTransferKind::Free && holder >= 0 && holder != config_.index)
                return context.error("AXIS_NOT_HELD",
                                     "FAX(" + name + "): process " + std::to_string(holder) +
                                         " holds the axis, not this process",
                                     word.column);
        }
    }
    if (!plan_.hasMotion) return true;
    const std::uint32_t notHeld = axesNotHeld();
    if (notHeld == 0) return true;
    for (int i = 0; i < axes_.count(); ++i) {
        if (!(notHeld & (1u << i)) || plan_.next.machine[static_cast<size_t>(i)] ==
                                          state_.modal.machine[static_cast<size_t>(i)])
            continue;
        const std::string name = axes_.axis(i).displayName();
        const int holder = axisTransfer_->holder(upper(name));
        return context.error("AXIS_NOT_HELD",
                             "axis " + name + " cannot move: " +
                                 (holder >= 0 ? "process " + std::to_string(holder) + " holds it"
                                              : std::string("it was released with FAX")) +
                                 " (GAX(" + name + ") first)");
    }
    return true;
}

void Interpreter::commitAxisTransfer(const AxisTransferCommand& transfer) {
    for (const std::string& name : transfer.axes) {
        const int axis = transferAxisIndex(name);
        if (axis < 0) continue;  // refused while planning
        const std::string key = upper(axes_.axis(axis).displayName());
        if (transfer.kind == AxisTransferKind::Free) {
            axisTransfer_->release(config_.index, key);
            continue;
        }
        const AxisTransfer::Ticket ticket = axisTransfer_->request(config_.index, key);
        if (!axisTransfer_->done(ticket)) axisWaits_.push_back({ticket, key});
    }
    if (!axisWaits_.empty()) holdRequested_ = true;
}

std::string Interpreter::waitingForAxis() const {
    for (const AxisWait& wait : axisWaits_)
        if (!axisTransfer_->done(wait.ticket)) return wait.axis;
    return {};
}

void Interpreter::withdrawAxisRequests() {
    if (axisTransfer_ && !axisWaits_.empty()) axisTransfer_->cancel(config_.index);
    axisWaits_.clear();
}

}  // namespace mtc::core
