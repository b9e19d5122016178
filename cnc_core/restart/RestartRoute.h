#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/Program.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/restart/LevelReach.h"
#include "cnc_core/restart/RestartSelection.h"
#include "cnc_core/restart/StartBlockSearch.h"

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
    ProgramPtr main;      ///< the selected program: the computing process starts at its N0000
    ProgramPtr selected;  ///< program of level 0 at the target (main, or the last JMP's program)
    ProgramPtr startProgram;
    std::uint32_t startBlock = 0;
    ProgramPtr startSelected;            ///< program of level 0 at the start block
    bool primary = false;                ///< start is the last primary block before the target
    std::vector<CallFrame> startFrames;  ///< call stack in force at the start block
    ProgramPtr targetProgram;
    std::uint32_t targetBlock = 0;
    std::vector<RouteFrame> targetChain;  ///< call stack at the target (outermost first)
    /// The program levels of the path, split at its JMPs (main program first).
    std::vector<LevelSegment> segments;
};

class ProgramScan;

/// What planRestartRoute and addStartWarnings work out about a program (its
/// LevelReach and which blocks a level reaches, the text scans of
/// ProgramScan), built on first use and kept: one start of the computing
/// process shares them between the route and its warnings, and the restart
/// verifier keeps one for all its targets. Programs must not change while
/// they are in it (a ProgramPtr is immutable). Not thread-safe.
class RestartRouteCache {
  public:
    RestartRouteCache();
    ~RestartRouteCache();
    /// LevelReach::reaches, from a kept block set per program and entries.
    bool reaches(const ProgramPtr& program, const std::vector<std::uint32_t>& entries,
                 std::uint32_t block);
    /// The kept LevelReach of `program`.
    const LevelReach& reach(const ProgramPtr& program);
    /// The kept ProgramScan of `program`.
    const ProgramScan& scan(const ProgramPtr& program);

  private:
    std::map<std::pair<const Program*, std::vector<std::uint32_t>>, LevelReach::BlockSet>
        reachable_;
    std::map<const Program*, std::unique_ptr<LevelReach>> reaches_;
    std::map<const Program*, std::unique_ptr<ProgramScan>> scans_;
    std::vector<ProgramPtr> keep_;  ///< the addresses above stay valid
};

/// Checks `selection` against the program memory (programs and blocks exist,
/// nothing in a cycle, every path block is a jump or call <Plane+> follows, at
/// most 10 program levels, runs 1..65536, every block of the path reached on
/// its program level) and works out the start block and the call chain of
/// the target (docs/decisions/restart.md ).
/// Fails (false, RESTART_* errors in `diagnostics`) on any problem; a
/// restart from the last primary block without one is a warning
/// (RESTART_NO_PRIMARY_BLOCK) and starts at the beginning of the program.
/// Without `cache`, one is made for this call.
bool planRestartRoute(const RestartSelection& selection, const ProgramStore& store,
                      RestartRoute& route, DiagnosticList& diagnostics,
                      RestartRouteCache* cache = nullptr);

/// True when the interpreter's call stack `stack` is the one `chain` describes.
bool callStackMatches(const std::vector<CallFrame>& stack, const std::vector<RouteFrame>& chain);

/// True when the interpreter at `state` stands where `route`'s target counts:
/// the call stack of the path on the level-0 program of the path (after its
/// last JMP, R-024).
bool atRouteLevel(const InterpreterState& state, const RestartRoute& route);

/// The warnings of seed 000, 2.4 and 5.1 for a planned route (restart-screen
/// RS-011): RESTART_START_BLOCK_NEEDED (the program starts with a subroutine
/// and the computing process would run into it), RESTART_START_AFTER_G91 /
/// RESTART_START_AFTER_G51 (the primary start block lies after G91 / G51).
/// The CLI and the screen both get them through ComputingProcess::begin.
void addStartWarnings(const RestartRoute& route, DiagnosticList& diagnostics,
                      RestartRouteCache* cache = nullptr);

}  // namespace mtc::core
