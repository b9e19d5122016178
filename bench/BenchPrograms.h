// Generated NC programs shared by the interpreter and restart benchmarks:
// one generator and one fixture (demo cell, parsed program in a store), so
// both benchmarks measure the same blocks.
#pragma once

#include <string>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/restart/ComputingProcess.h"

namespace mtc::bench {

/// What the generated program holds besides its moves.
struct GeneratedProgramOptions {
    bool mixed = false;       ///< aux functions (M/Q) and arithmetic on every other block
    bool endWithM30 = false;  ///< a final "N9999 M30" block
};

/// `blocks` blocks in cycles of four that always close: a line to the start
/// of a quarter circle, a counter-clockwise and a clockwise quarter circle
/// (radius 10, centre absolute), a line back. The square's size varies so the
/// numbers differ from cycle to cycle.
std::string generateClosedMotionProgram(int blocks, GeneratedProgramOptions options = {});

/// The demo cell and a generated program parsed as program 1 of process 0.
struct BenchProgramFixture {
    /// Parses the generated program of `blocks` blocks into the store.
    BenchProgramFixture(int blocks, GeneratedProgramOptions options);
    mtc::core::MachineConfig cell;
    mtc::core::ProgramStore store;
    mtc::core::ProgramPtr program;
};

/// The restart computing process of process 0 on a fixture's program, to
/// its last block but the M30 (BM_RestartComputingProcess*, mtc_one_run).
struct ComputingProcessRun {
    explicit ComputingProcessRun(const BenchProgramFixture& fixture);
    /// ComputingProcess::begin for the selection; false on an error.
    bool begin(mtc::core::DiagnosticList& diagnostics);
    mtc::core::NullSink sps;
    mtc::core::InterpreterServices services;
    mtc::core::Interpreter live;  ///< the interrupted run whose state the restart starts from
    mtc::core::ComputingProcess computing;
    mtc::core::RestartSelection selection;
};

}  // namespace mtc::bench
