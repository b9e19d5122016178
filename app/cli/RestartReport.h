#pragma once

#include <optional>
#include <vector>

#include "cli/JsonWriter.h"
#include "cli/RestartRecorder.h"
#include "cli/StateOutput.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/SignalTable.h"
#include "cnc_core/removal/ReentryCollisions.h"
#include "cnc_core/restart/RestartSequence.h"

namespace mtc::cli {

/// A State (CLI-CONTRACT.md) taken at one moment: the interpreter state with
/// what the JSON needs besides it.
struct StateSnapshot {
    core::InterpreterState state;
    Page61Buffers page61;
    std::vector<double> positions;
};

/// Copies the state of `interpreter` with its page 61 buffers from `data`.
StateSnapshot takeSnapshot(const core::Interpreter& interpreter,
                           const core::MachineDataProvider& data, int process);

/// Everything `restart` prints.
struct RestartReport {
    const core::ProcessConfig* process = nullptr;
    const core::Interpreter* interpreter = nullptr;  ///< for axes and axis names
    const core::RestartSequence* sequence = nullptr;
    bool accepted = false;         ///< the selection was accepted (target and start known)
    bool adjust = false;           ///< --adjust
    bool checkCollisions = false;  ///< --check-collisions
    /// The way back checked against the part at the target (with
    /// --check-collisions; none when the target was not reached).
    std::optional<core::removal::ReentryCheck> collisions;
    core::DiagnosticList diagnostics;
    std::optional<StateSnapshot> computed;  ///< after the computing process (or as far as it got)
    std::optional<StateSnapshot> final;     ///< after REPOS (with --adjust)
    const RestartRecorder* recorder = nullptr;
    const core::SignalTable* signals = nullptr;
};

/// Writes the one JSON document of `restart`.
void writeRestartJson(JsonWriter& json, const RestartReport& report);
/// Prints the same as readable text to stdout.
void printRestartText(const RestartReport& report);

}  // namespace mtc::cli
