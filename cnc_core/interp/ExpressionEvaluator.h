#pragma once

#include <string>

#include "cnc_core/interp/BlockInput.h"
#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/interp/VariableAccess.h"
#include "cnc_core/language/Program.h"
#include "cnc_core/machine/MachineDataProvider.h"

namespace mtc::core {

class AdaptiveFeedControl;

/// Why an evaluation failed: a stable code and a readable message.
struct EvaluationError {
    std::string code;
    std::string message;
};

/// Evaluates expression trees of a Program against the interpreter state.
/// Reads see the state at the start of the block plus the variable writes
/// made earlier in the same block (assignments run left to right).
class ExpressionEvaluator {
  public:
    /// Everything an expression may read. Pointers may be null where the
    /// service is absent (reads through it then fail with a diagnostic).
    struct Context {
        const InterpreterState* state = nullptr;
        const BlockInput* pending = nullptr;
        const MachineDataProvider* machineData = nullptr;
        const VariableAccess* otherProcesses = nullptr;
        int process = 0;
        const AdaptiveFeedControl* adaptiveFeed = nullptr;  ///< AXD(axis:P-7-3652)
    };

    explicit ExpressionEvaluator(Context context) : context_(context) {}
    /// Where AXD(axis:P-7-3652) reads the measured stall torque (nullptr = nowhere).
    void setAdaptiveFeed(const AdaptiveFeedControl* afc) { context_.adaptiveFeed = afc; }

    /// Value of node `node` of `program` into `value`. Returns false and
    /// fills `error` on division by zero, a bad variable number, an unknown
    /// group in M()/G(), a failed MTD read or a malformed tree.
    bool evaluate(const Program& program, std::int32_t node, double& value,
                  EvaluationError& error) const;
    /// Turns MTD argument nodes a..d into an address (defaults: process =
    /// running process, sub = 0; the parser puts the element in d).
    bool machineDataAddress(const Program& program, const ExprNode& node,
                            MachineDataAddress& address, EvaluationError& error) const;
    /// Reads variable @index (process -1 = own) honouring pending writes.
    bool readVariable(int process, int index, double& value, EvaluationError& error) const;

  private:
    bool eval(const Program& program, std::int32_t node, int depth, double& value,
              EvaluationError& error) const;
    bool evalBinary(const Program& program, const ExprNode& node, int depth, double& value,
                    EvaluationError& error) const;
    bool evalRead(const Program& program, const ExprNode& node, int depth, double& value,
                  EvaluationError& error) const;
    bool readDriveData(const ExprNode& node, double& value, EvaluationError& error) const;
    bool optionalInt(const Program& program, std::int32_t node, int depth, int fallback, int& out,
                     EvaluationError& error) const;

    Context context_;
};

}  // namespace mtc::core
