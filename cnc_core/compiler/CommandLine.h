#pragma once

#include <string>
#include <string_view>
#include <vector>

/// External commands without a shell (docs/DECISIONS.md D-010): a user
/// compiler command is a program and its arguments, split like the shell
/// splits words (blanks, '...', "...", backslash) but never interpreted by
/// one: `;`, `|`, `&`, `<`, `>`, `$(...)` and backquotes outside quotes are
/// refused, so what the operator saw is exactly what runs.
namespace mtc::core {

/// Splits `command` into words. False with `problem` for an empty command,
/// an unclosed quote, a trailing backslash or an unquoted shell operator.
bool splitCommandLine(std::string_view command, std::vector<std::string>& words,
                      std::string& problem);

/// How a command ended.
struct CommandOutcome {
    bool started = false;   ///< false: the program could not be started (`problem` says why)
    bool timedOut = false;  ///< killed after the time limit
    int exitStatus = -1;    ///< exit status when it exited normally, else -1
    std::string problem;    ///< "" when it ran and exited
};

/// Runs `arguments` (program looked up in PATH, then its arguments) with
/// no shell in between, in the current directory, waits at most
/// `timeoutSeconds` (then kills it). Never throws.
CommandOutcome runCommand(const std::vector<std::string>& arguments, double timeoutSeconds);

}  // namespace mtc::core
