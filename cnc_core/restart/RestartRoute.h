#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/Program.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/restart/RestartSelection.h"

namespace mtc::core {

/// What <Plane+> does with a jump or call command (seed 000, 2.5).
enum class PathStepKind {
    None,    ///< no jump word, or one <Plane+> cannot follow (BST, RET, RTS)
    Branch,  ///< BRA, BEQ, BNE, BPL, BMI, BRF, BSE, BTE, BES, BER: same program level
    Call,    ///< BSR, BEV (label), JSR, JEV (program): opens a program level
    Jump,    ///< JMP: another program; the levels before it are left
};

/// How <Plane+> treats jump command `kind`.
PathStepKind pathStepKind(JumpKind kind);

/// The jump word of block `block` of `program`, if it has one.
std::optional<Word> jumpWordOf(const Program& program, std::uint32_t block);

/// "N0012" (or "block 7" for an unnumbered block) with program and line, for diagnostics.
SourceLocation locationOf(const Program& program, std::uint32_t block);

/// One saved return point the target must be reached with: the program and
/// block of the call command.
struct RouteFrame {
    int program = 0;
    std::uint32_t callBlock = 0;
};

/// Where the computing process starts and with which call stack the target
/// block counts as reached. Built from a RestartSelection by planRestartRoute.
struct RestartRoute {
    ProgramPtr selected;  ///< program of level 0 (the main program, or the last JMP's program)
    ProgramPtr startProgram;
    std::uint32_t startBlock = 0;
    bool primary = false;                ///< start is the last primary block before the target
    std::vector<CallFrame> startFrames;  ///< call stack in force at the start block
    ProgramPtr targetProgram;
    std::vector<RouteFrame> targetChain;  ///< call stack at the target (outermost first)
};

/// Checks `selection` against the program memory (programs and blocks exist,
/// nothing in a cycle, every path block is a jump or call <Plane+> follows, at
/// most 10 program levels, runs 1..65536) and works out the start block and
/// the call chain of the target (docs/decisions/restart.md ).
/// Fails (false, RESTART_* errors in `diagnostics`) on any problem; a
/// restart from the last primary block without one is a warning
/// (RESTART_NO_PRIMARY_BLOCK) and starts at the beginning of the program.
bool planRestartRoute(const RestartSelection& selection, const ProgramStore& store,
                      RestartRoute& route, DiagnosticList& diagnostics);

/// True when the interpreter's call stack `stack` is the one `chain` describes.
bool callStackMatches(const std::vector<CallFrame>& stack, const std::vector<RouteFrame>& chain);

}  // namespace mtc::core
