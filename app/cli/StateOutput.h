#pragma once

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/JsonWriter.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/ProcessAxes.h"

namespace mtc::cli {

/// The 40-entry buffers of machine data page 61 (oldest first, 0 = empty).
struct Page61Buffers {
    std::array<double, 40> m16{};
    std::array<double, 40> q{};
};

/// What the State object of CLI-CONTRACT.md is made from.
struct StateView {
    const core::InterpreterState& state;
    const core::ProcessConfig& process;
    const core::ProcessAxes& axes;
    const Page61Buffers& page61;
    const std::vector<std::string>& axisNames;  ///< per machine axis; "" = not reported
    const std::vector<double>& positions;       ///< programmed position per machine axis
    /// Where tool compensation (radius, edge, length) put the axes, machine
    /// positions per machine axis; nullptr (or empty) when they stand at the
    /// programmed positions. Reported as "axis_position".
    const std::vector<double>* axisPositions = nullptr;
};

/// The axis positions of `interpreter` when tool compensation moved them
/// away from the commanded machine positions, otherwise empty.
std::vector<double> compensatedAxisPositions(const core::Interpreter& interpreter);

/// Axis names of the machine axes (Interpreter::axisName, designation 1) for
/// motion records and as the list of reported axes; spindles without rotary
/// axis capability are "". Positions in a State are named by the state's own
/// transformation (designation 2 under G31/G32, core::programmedAxisName).
std::vector<std::string> reportedAxisNames(const core::Interpreter& interpreter);

/// The programmed position of every machine axis (Interpreter::programmedPosition).
std::vector<double> programmedPositions(const core::Interpreter& interpreter);

/// Reads the page 61 buffers of `process` from `machineData` (0 where unreadable).
Page61Buffers readPage61(const core::MachineDataProvider& machineData, int process);

/// Writes the contract's State object (g, m_groups, page61, page60, s, t, e,
/// f, variables, position, call_stack) as the next JSON value.
void writeStateJson(JsonWriter& json, const StateView& view);

/// Prints the same state as readable lines to `stream`, the first one
/// starting with `label` ("final: G ...").
void printStateText(std::FILE* stream, const StateView& view, const char* label = "final");

}  // namespace mtc::cli
