#pragma once

#include <string>
#include <string_view>

#include "cnc_core/interp/BlockInput.h"
#include "cnc_core/interp/ExpressionEvaluator.h"
#include "cnc_core/interp/ModalGroups.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/Program.h"
#include "cnc_core/machine/AxisNameTable.h"
#include "cnc_core/machine/ProcessAxes.h"

namespace mtc::core {

/// Where a diagnostic of block `blockIndex` of `program` points.
SourceLocation blockLocation(const Program& program, std::uint32_t blockIndex, int column = 0);

/// First stage of a block: reads its words into a BlockInput, evaluating
/// every expression and assignment (left to right) and checking each word on
/// its own: known G function, one G per group, known axis name for the
/// process, no word twice, integer values where integers are required.
/// Changes nothing but `input` and `diagnostics`. One decoder per block; the
/// error paths live in separate functions so that the per-word path stays short.
class BlockDecoder {
  public:
    struct Target {
        const Program& program;
        std::uint32_t blockIndex;
        BlockInput& input;
        DiagnosticList& diagnostics;
        /// InterpreterOptions::shortcuts: after a usual block only its fields are cleared.
        bool shortcuts = false;
    };

    BlockDecoder(const ProcessAxes& axes, const AxisNameTable& names,
                 const ExpressionEvaluator& evaluator, Target target)
        : axes_(axes), names_(names), evaluator_(evaluator), t_(target) {}

    /// Decodes `block` (block `blockIndex` of the program) into the input.
    /// Returns false when an error was added (warnings do not fail).
    bool decode(const Block& block) const;

  private:
    /// A word the 8-byte form does not hold (expressions, jumps, commands, ...).
    bool wholeWord(std::uint32_t index) const;
    bool numberWord(const NumberWord& w) const;
    bool value(const NumberWord& w, double& out) const {
        if (w.expr < 0) {
            out = w.number;
            return true;
        }
        return evaluated(w.expr, w.column, out);
    }
    bool value(const Word& w, double& out) const { return value(numberWordOf(w), out); }
    bool integer(std::uint16_t column, double v, int& out, const char* what) const {
        if (v >= 0 && v <= 1e8 && v == static_cast<double>(static_cast<int>(v))) {
            out = static_cast<int>(v);
            return true;
        }
        return notInteger(column, v, what);
    }
    bool gWord(const NumberWord& w) const;
    bool auxWord(const NumberWord& w) const;
    bool spindleWord(const NumberWord& w) const;
    bool scalarWord(const NumberWord& w) const;
    bool axisWord(const NumberWord& w) const;
    bool centerWord(const NumberWord& w) const;
    bool assignment(const Word& w) const;
    bool machineDataAssignment(const Word& w) const;
    bool jumpWord(const Word& w, std::uint32_t index) const;
    bool commandWord(const Word& w, std::uint32_t index) const;
    /// AXD(axis:P-7-3651)=period into BlockInput::stallRecording.
    bool stallRecording(const Word& w) const;

    // Error paths (cold).
    bool evaluated(std::int32_t expr, std::uint16_t column, double& out) const;
    bool notInteger(std::uint16_t column, double v, const char* what) const;
    bool badG(std::uint16_t column, int number, const GCodeInfo& info, int other) const;
    /// An axis name that is not plainly this process's: true (with the
    /// warning) for designation 1 of a transformed linear axis, else the error.
    [[gnu::cold, gnu::noinline]] bool unusualAxisName(NumberWord w) const;
    // By value: the hot callers keep their word in registers.
    bool badAxis(NumberWord w, AxisLookup found) const;
    void designationOneWarning(NumberWord w, AxisLookup found) const;
    bool twice(std::uint16_t column, std::string_view what) const;
    bool axisFunctionConflict(std::uint16_t column, int number) const;
    bool noSpindle(std::uint16_t column, int slot) const;
    bool error(std::uint16_t column, const std::string& code, const std::string& message) const;
    /// The same for fixed texts: the hot word handlers build no string.
    bool error(std::uint16_t column, const char* code, const char* message) const;

    const ProcessAxes& axes_;
    const AxisNameTable& names_;
    const ExpressionEvaluator& evaluator_;
    Target t_;
};

}  // namespace mtc::core
