#include "cnc_core/interp/ProgramFlow.h"

#include <cmath>

namespace mtc::core {
namespace {

bool branchTaken(JumpKind kind, double condition) {
    switch (kind) {
        case JumpKind::BEQ:
            return condition == 0.0;
        case JumpKind::BNE:
            return condition != 0.0;
        case JumpKind::BPL:
            return condition >= 0.0;
        case JumpKind::BMI:
            return condition < 0.0;
        default:
            return true;
    }
}

}  // namespace

bool ProgramFlow::findLabel(const ProgramPtr& current, std::string_view name, ProgramPtr& program,
                            std::uint32_t& block) const {
    return store_.findLabel(process_, current, name, program, block);
}

bool ProgramFlow::label(const BlockContext& c, const InterpreterState& state,
                        std::uint32_t wordIndex, std::string_view name, int column,
                        FlowPlan& flow) {
    CacheEntry& entry = cache_[state.program.get()];
    if (!entry.keepAlive) entry.keepAlive = state.program;
    auto hit = entry.words.find(wordIndex);
    if (hit != entry.words.end()) {
        flow.program = hit->second.program;
        flow.block = hit->second.block;
        return true;
    }
    Resolved resolved;
    if (name.empty()) return c.error("LABEL_MISSING", "the jump has no label", column);
    if (!findLabel(state.program, name, resolved.program, resolved.block))
        return c.error("LABEL_NOT_FOUND",
                       "label ." + std::string(name) + " is neither in program " +
                           std::to_string(state.program->number) +
                           ", nor in program 99, nor in the cycle memory",
                       column);
    entry.words.emplace(wordIndex, resolved);
    flow.program = resolved.program;
    flow.block = resolved.block;
    return true;
}

bool ProgramFlow::program(const BlockContext& c, double number, int column, FlowPlan& flow) const {
    const int n = static_cast<int>(number);
    flow.program = store_.find(process_, n);
    flow.block = 0;
    if (!flow.program)
        return c.error("PROGRAM_NOT_FOUND",
                       "program " + std::to_string(n) + " does not exist in process " +
                           std::to_string(process_),
                       column);
    return true;
}

bool ProgramFlow::event(const BlockContext& c, const Word& word, bool& set) const {
    const int process = word.eventProcess < 0 ? process_ : word.eventProcess;
    if (!EventTable::valid(process, word.eventNumber))
        return c.error("EVENT_INVALID",
                       "event " + std::to_string(process) + ":" + std::to_string(word.eventNumber) +
                           " does not exist (process 0..6, event 0..255)",
                       word.column);
    set = events_ && events_->get(process, word.eventNumber);
    return true;
}

bool ProgramFlow::callAllowed(const BlockContext& c, const InterpreterState& state,
                              int column) const {
    if (state.callStack.size() + 1 < static_cast<std::size_t>(kMaxCallLevels)) return true;
    return c.error("CALL_DEPTH",
                   "a call would open program level 11; at most 10 levels (the main program and 9 "
                   "nested calls) are allowed",
                   column);
}

bool ProgramFlow::plan(const BlockContext& c, const BlockInput& in, const InterpreterState& state,
                       const ModalState& next, FlowPlan& flow) {
    flow.kind = FlowPlan::Kind::Next;
    if (in.jumpWord < 0) return true;
    const auto wordIndex = static_cast<std::uint32_t>(in.jumpWord);
    const Word w = c.program.words[wordIndex];
    const std::string_view name = c.program.text(w.text);
    const double condition = in.conditionSet ? in.condition : state.condition;
    bool eventSet = false;
    switch (w.jump) {
        case JumpKind::BRA:
        case JumpKind::BEQ:
        case JumpKind::BNE:
        case JumpKind::BPL:
        case JumpKind::BMI:
            if (!branchTaken(w.jump, condition)) return true;
            flow.kind = FlowPlan::Kind::Goto;
            return label(c, state, wordIndex, name, w.column, flow);
        case JumpKind::BST:
        case JumpKind::RET:
            flow.kind = FlowPlan::Kind::End;
            return true;
        case JumpKind::RTS:
            if (state.callStack.empty())
                return c.error("RTS_WITHOUT_CALL", "RTS without a subroutine call", w.column);
            flow.kind = FlowPlan::Kind::Return;
            return true;
        case JumpKind::BSR:
            flow.kind = FlowPlan::Kind::Call;
            return callAllowed(c, state, w.column) &&
                   label(c, state, wordIndex, name, w.column, flow);
        case JumpKind::JSR:
            flow.kind = FlowPlan::Kind::Call;
            return callAllowed(c, state, w.column) && program(c, in.jumpProgram, w.column, flow);
        case JumpKind::JMP:
            flow.kind = FlowPlan::Kind::Jump;
            return program(c, in.jumpProgram, w.column, flow);
        case JumpKind::BES:
        case JumpKind::BER:
            if (!event(c, w, eventSet)) return false;
            if (eventSet != (w.jump == JumpKind::BES)) return true;
            flow.kind = FlowPlan::Kind::Goto;
            return label(c, state, wordIndex, name, w.column, flow);
        case JumpKind::BEV:
        case JumpKind::JEV:
            if (!event(c, w, eventSet)) return false;
            if (!eventSet) return true;
            flow.kind = FlowPlan::Kind::Call;
            if (!callAllowed(c, state, w.column)) return false;
            return w.jump == JumpKind::BEV ? label(c, state, wordIndex, name, w.column, flow)
                                           : program(c, in.jumpProgram, w.column, flow);
        case JumpKind::BTE:
        case JumpKind::BSE: {
            const bool taken = w.jump == JumpKind::BTE ? next.tool == 0 : next.toolSpindle[0] == 0;
            if (!taken) return true;
            flow.kind = FlowPlan::Kind::Goto;
            return label(c, state, wordIndex, name, w.column, flow);
        }
        case JumpKind::BRF: {
            // Its condition rests on a state the simulator does not model, so
            // it is never met: the label must exist, the flow goes on (I-019).
            FlowPlan labelOnly;
            return label(c, state, wordIndex, name, w.column, labelOnly);
        }
    }
    return c.error("JUMP_NOT_SUPPORTED", "unknown jump", w.column);
}

}  // namespace mtc::core
