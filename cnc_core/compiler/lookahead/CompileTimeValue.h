#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mtc::core::lookahead {

/// Reads NC variable `@process:number` of the controller at compile time
/// (ACD_COMP, seed 001 ch. 6); nullopt = not available.
using NcVariableReader = std::function<std::optional<double>(int process, int number)>;

/// Result of evaluating a compile-time value.
struct CompileTimeValue {
    bool ok = false;
    double value = 0.0;
    std::string problem;  ///< why not ok
    /// ACD_COMP reads that found no controller value and used 0 ("@1:120").
    std::vector<std::string> unreadVariables;
};

/// Evaluates the value of a look-ahead variable as written after '=':
/// numbers (decimal point or comma), + - * / and parentheses, and
/// ACD_COMP[@n] / ACD_COMP[@p:n] / ACD[...] (the current value of NC
/// variable n of process p, default `process`, read through `reader`;
/// without a value it reads 0 and lists the variable in unreadVariables).
CompileTimeValue evaluateCompileTimeValue(std::string_view text, int process,
                                          const NcVariableReader& reader);

}  // namespace mtc::core::lookahead
