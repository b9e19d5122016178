#pragma once

#include <cstdint>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/language/Program.h"

namespace mtc::core {

/// Runs one MDI entry's program on a station's interpreter from the state
/// the station is in (MDI-002): modal G functions, M groups, S, T, F,
/// positions and variables are kept, before and after. When the entry's last
/// block is done the run ends WITHOUT the program-end resets (an M30 / M02 in
/// the entry still resets, like in a program) and the interpreter goes back
/// to the program that was selected before (its pointer on the first block).
class MdiRun {
  public:
    /// Selects `program` on `interpreter` (not owned; must outlive the run).
    /// False with `diagnostics` when the interpreter refuses it.
    bool begin(Interpreter& interpreter, ProgramPtr program, DiagnosticList* diagnostics = nullptr);
    /// Executes at most one block of the entry. Ended with the entry's last
    /// block (then the run is over, no extra step for the end); Error ends the run as well (the
    /// state is the one before the rejected block); Stopped (M00, a held GAX) keeps it.
    RunResult step();
    /// Steps until the entry ends, stops, fails or `budget` blocks ran
    /// (BLOCK_BUDGET; the run is abandoned).
    RunResult run(std::uint64_t budget = kDefaultBlockBudget);
    /// Ends the run now (Control reset, an error): the interpreter gets the
    /// previously selected program back; the state stays as it is.
    void abandon();
    /// True between begin() and the end of the entry.
    bool active() const { return interpreter_ != nullptr; }
    /// The entry's program (nullptr when none ran yet).
    const ProgramPtr& program() const { return program_; }

  private:
    bool entryDone() const;

    Interpreter* interpreter_ = nullptr;
    ProgramPtr program_;
    ProgramPtr previous_;
};

}  // namespace mtc::core
