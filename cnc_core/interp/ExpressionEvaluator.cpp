#include "cnc_core/interp/ExpressionEvaluator.h"

#include "cnc_core/afc/AdaptiveFeedControl.h"

#include <cmath>

namespace mtc::core {
namespace {

constexpr int kMaxDepth = 64;

// Every error is out of line: built in place, their strings gave the hot
// functions (a tree walk, a variable read, an operator) large frames and six
// saved registers per call. A fixed text is passed as it is, so that the
// caller builds no string either.
[[gnu::cold, gnu::noinline]] bool fail(EvaluationError& error, const char* code,
                                       std::string message) {
    error.code = code;
    error.message = std::move(message);
    return false;
}

[[gnu::cold, gnu::noinline]] bool fail(EvaluationError& error, const char* code,
                                       const char* message) {
    return fail(error, code, std::string(message));
}

[[gnu::cold, gnu::noinline]] bool noSuchVariable(EvaluationError& error, int index) {
    return fail(error, "VARIABLE_RANGE",
                "variable @" + std::to_string(index) + " does not exist (0.." +
                    std::to_string(kVariableCount - 1) + ")");
}

[[gnu::cold, gnu::noinline]] bool noSuchProcess(EvaluationError& error, int process, int index) {
    return fail(error, "VARIABLE_PROCESS",
                "variable @" + std::to_string(process) + ":" + std::to_string(index) +
                    " cannot be read: no such process");
}

bool isGroupUsed(int group) {
    for (int g : usedGGroups())
        if (g == group) return true;
    return false;
}

}  // namespace

bool ExpressionEvaluator::evaluate(const Program& program, std::int32_t node, double& value,
                                   EvaluationError& error) const {
    return eval(program, node, 0, value, error);
}

bool ExpressionEvaluator::readVariable(int process, int index, double& value,
                                       EvaluationError& error) const {
    const bool own = process < 0 || process == context_.process;
    if (index < 0 || index >= kVariableCount) return noSuchVariable(error, index);
    if (!own) {
        if (!context_.otherProcesses || !context_.otherProcesses->read(process, index, value))
            return noSuchProcess(error, process, index);
        return true;
    }
    if (context_.pending) {
        const BlockInput& p = *context_.pending;
        for (int i = p.writeCount - 1; i >= 0; --i) {
            const auto& w = p.writes[static_cast<size_t>(i)];
            if (w.index == index && (w.process < 0 || w.process == context_.process)) {
                value = w.value;
                return true;
            }
        }
    }
    value = context_.state->variables.values[static_cast<size_t>(index)];
    return true;
}

bool ExpressionEvaluator::eval(const Program& program, std::int32_t node, int depth, double& value,
                               EvaluationError& error) const {
    if (node < 0 || static_cast<size_t>(node) >= program.expressions.size())
        return fail(error, "EXPRESSION_MALFORMED", "expression refers to a missing node");
    if (depth > kMaxDepth)
        return fail(error, "EXPRESSION_TOO_DEEP", "expression nested deeper than 64 levels");
    const ExprNode& n = program.expressions[static_cast<size_t>(node)];
    switch (n.op) {
        case ExprOp::Constant:
            value = n.value;
            return true;
        case ExprOp::Variable:
            return readVariable(n.process, n.index, value, error);
        case ExprOp::Negate:
            if (!eval(program, n.a, depth + 1, value, error)) return false;
            value = -value;
            return true;
        case ExprOp::Add:
        case ExprOp::Subtract:
        case ExprOp::Multiply:
        case ExprOp::Divide:
            return evalBinary(program, n, depth, value, error);
        default:
            return evalRead(program, n, depth, value, error);
    }
}

bool ExpressionEvaluator::evalBinary(const Program& program, const ExprNode& n, int depth,
                                     double& value, EvaluationError& error) const {
    double left = 0, right = 0;
    if (!eval(program, n.a, depth + 1, left, error) || !eval(program, n.b, depth + 1, right, error))
        return false;
    switch (n.op) {
        case ExprOp::Add:
            value = left + right;
            break;
        case ExprOp::Subtract:
            value = left - right;
            break;
        case ExprOp::Multiply:
            value = left * right;
            break;
        default:
            if (right == 0.0) return fail(error, "DIVISION_BY_ZERO", "division by zero");
            value = left / right;
            break;
    }
    if (!std::isfinite(value))
        return fail(error, "ARITHMETIC_OVERFLOW", "arithmetic result is not a finite number");
    return true;
}

bool ExpressionEvaluator::evalRead(const Program& program, const ExprNode& n, int depth,
                                   double& value, EvaluationError& error) const {
    const InterpreterState& s = *context_.state;
    int group = 0;
    switch (n.op) {
        case ExprOp::ReadM:
            if (!optionalInt(program, n.a, depth, -1, group, error)) return false;
            if (group < 1 || group > 16)
                return fail(error, "BAD_M_GROUP",
                            "M(" + std::to_string(group) + "): M groups are 1..16");
            value = s.mGroups[static_cast<size_t>(group)];
            return true;
        case ExprOp::ReadG:
            if (!optionalInt(program, n.a, depth, -1, group, error)) return false;
            if (!isGroupUsed(group))
                return fail(error, "BAD_G_GROUP",
                            "G(" + std::to_string(group) + "): no such G code group");
            value = s.modal.g[static_cast<size_t>(group)];
            return true;
        case ExprOp::ReadT:
            value = s.modal.tool;
            return true;
        case ExprOp::ReadE:
            value = s.modal.edge;
            return true;
        case ExprOp::ReadQ:  // the last Q function, -1 since program end (seed 000, 3.1)
            value = s.lastQ;
            return true;
        case ExprOp::ReadS: {
            const int spindle = n.index == 0 ? s.modal.referenceSpindle : n.index;
            if (spindle < 1 || spindle >= kSpindleSlots)
                return fail(error, "AXIS_UNKNOWN", "no spindle S" + std::to_string(spindle));
            value = s.modal.spindleSpeed[static_cast<size_t>(spindle)];
            return true;
        }
        case ExprOp::ReadSPC:
            value = s.modal.referenceSpindle;
            return true;
        case ExprOp::ReadTime:
            value = s.modal.time;
            return true;
        case ExprOp::ReadMTD: {
            MachineDataAddress address;
            if (!machineDataAddress(program, n, address, error)) return false;
            if (!context_.machineData)
                return fail(error, "MTD_UNAVAILABLE", "no machine data available");
            const MachineDataStatus status = context_.machineData->read(address, value);
            if (status != MachineDataStatus::Ok)
                return fail(error, machineDataStatusCode(status),
                            "MTD(" + std::to_string(address.page) + "," +
                                std::to_string(address.process) + "," +
                                std::to_string(address.sub) + "," +
                                std::to_string(address.element) + ") cannot be read");
            return true;
        }
        case ExprOp::ReadAXD:
            return readDriveData(n, value, error);
        default:
            return fail(error, "EXPRESSION_MALFORMED", "unknown expression operator");
    }
}

bool ExpressionEvaluator::readDriveData(const ExprNode& n, double& value,
                                        EvaluationError& error) const {
    std::string axis(1, static_cast<char>(n.index / 10));
    if (n.index % 10 != 0) axis += static_cast<char>('0' + n.index % 10);
    if (static_cast<int>(n.value) != 3652)
        return fail(error, "AXD_NOT_READABLE",
                    "AXD(" + axis + ":P-7-" + std::to_string(static_cast<int>(n.value)) +
                        "): only P-7-3652 (measured stall torque) can be read");
    if (!context_.adaptiveFeed)
        return fail(error, "AXD_NOT_READABLE", "this process has no drive data to read");
    value = context_.adaptiveFeed->measuredStallTorque(axis);
    return true;
}

bool ExpressionEvaluator::optionalInt(const Program& program, std::int32_t node, int depth,
                                      int fallback, int& out, EvaluationError& error) const {
    if (node < 0) {
        out = fallback;
        return true;
    }
    double v = 0;
    if (!eval(program, node, depth + 1, v, error)) return false;
    if (v != std::floor(v) || std::fabs(v) > 1e9)
        return fail(error, "NOT_AN_INTEGER", "expected a whole number, got " + std::to_string(v));
    out = static_cast<int>(v);
    return true;
}

bool ExpressionEvaluator::machineDataAddress(const Program& program, const ExprNode& n,
                                             MachineDataAddress& address,
                                             EvaluationError& error) const {
    // The parser stores the element in d whatever the argument count (with
    // three arguments the third is the element); c is the sub index.
    const std::int32_t elementNode = n.d;
    const std::int32_t subNode = n.c;
    if (n.a < 0 || elementNode < 0)
        return fail(error, "MTD_ARGUMENTS", "MTD needs a page and an element");
    return optionalInt(program, n.a, 0, 0, address.page, error) &&
           optionalInt(program, n.b, 0, context_.process, address.process, error) &&
           optionalInt(program, subNode, 0, 0, address.sub, error) &&
           optionalInt(program, elementNode, 0, 0, address.element, error);
}

}  // namespace mtc::core
