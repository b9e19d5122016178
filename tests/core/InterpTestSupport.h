#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/program/ProgramStore.h"

namespace mtc::test {

/// The built-in demo cell (MACHINES.md); the test fails if it does not load.
const core::MachineConfig& demoCell();
/// A cell read from configuration text; diagnostics become test failures.
core::MachineConfig cellFromText(const std::string& text);

/// Parses `source` as program `number`; parse diagnostics are kept in the program.
core::ProgramPtr parse(const std::string& source, int number);

/// Writes every sink call as one transcript line, in order:
///   motion N0010 L3 linear X=10.0000 Y=5.0000 F=1000.0000
///   (tool compensation: "... | programmed X=.. Y=.. | tool centre X=.. Y=.."
///   and "motion N0010 L3 inserted cw ..." for a corner element)
///   aux N0011 L4 M3 / S1=1500 / T7
///   dwell N0012 L5 2.0000
///   command N0013 L6 MTP ()
class TranscriptSink : public core::MachineSink {
  public:
    explicit TranscriptSink(std::vector<std::string> axisNames) : names_(std::move(axisNames)) {}
    void setNames(std::vector<std::string> axisNames) { names_ = std::move(axisNames); }
    void motion(const core::Motion& m) override;
    void auxiliary(const core::AuxOutput& a) override;
    void dwell(const core::SourceLocation& where, double seconds) override;
    void command(const core::MachineCommand& command) override;
    std::string text;

  private:
    std::vector<std::string> names_;
};

/// "12.5000" with "-0.0000" printed as "0.0000".
std::string number(double value);
/// "N0012 L14" (or "- L14" for an unnumbered block).
std::string where(const core::SourceLocation& location);
/// One line per diagnostic: "error CODE N0012 L14 C5: message | detail | detail".
std::string diagnosticsText(const core::DiagnosticList& diagnostics);
/// The interpreter state as transcript lines (G groups, M groups, Q, S, T,
/// E, F, positions, written variables, call stack).
std::string stateText(const core::Interpreter& interpreter);

/// A process of a cell with a program store, a transcript sink and an
/// interpreter over them: the fixture of most interpreter tests.
struct Station {
    Station(const core::MachineConfig& cell, int process);
    /// Parses and stores program `number`; returns it.
    core::ProgramPtr add(const std::string& source, int number);
    /// add() + select() + run(); returns the result.
    core::RunResult run(const std::string& source, int number = 1,
                        std::uint64_t budget = core::kDefaultBlockBudget);

    const core::ProcessConfig& config;
    core::ProgramStore store;
    std::unique_ptr<TranscriptSink> sink;
    std::unique_ptr<core::Interpreter> interpreter;
    /// Adaptive feed control of the process on the interpreter's machine
    /// data (G26 switches, no machine slows the moves).
    std::shared_ptr<core::AdaptiveFeedControl> afc;
};

/// The codes of all error diagnostics, in order.
std::vector<std::string> errorCodes(const core::DiagnosticList& diagnostics);

}  // namespace mtc::test
