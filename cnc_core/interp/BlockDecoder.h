#pragma once

#include "cnc_core/interp/BlockInput.h"
#include "cnc_core/interp/ExpressionEvaluator.h"
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
/// Changes nothing but `input` and `diagnostics`.
class BlockDecoder {
  public:
    BlockDecoder(const ProcessAxes& axes, const AxisNameTable& names,
                 const ExpressionEvaluator& evaluator)
        : axes_(axes), names_(names), evaluator_(evaluator) {}

    /// Decodes block `blockIndex` of `program`. Returns false when an error
    /// was added to `diagnostics` (warnings do not fail).
    bool decode(const Program& program, const Block& block, std::uint32_t blockIndex,
                BlockInput& input, DiagnosticList& diagnostics) const;

  private:
    struct Cursor {
        const Program& program;
        std::uint32_t blockIndex;
        std::uint32_t wordIndex;
        const Word& word;
        BlockInput& input;
        DiagnosticList& diagnostics;
    };

    bool word(Cursor& c) const;
    bool value(Cursor& c, double& out) const {
        if (c.word.expr < 0) {
            out = c.word.number;
            return true;
        }
        return evaluated(c, out);
    }
    bool evaluated(Cursor& c, double& out) const;
    bool integer(Cursor& c, double v, int& out, const char* what) const {
        if (v >= 0 && v <= 1e8 && v == static_cast<double>(static_cast<int>(v))) {
            out = static_cast<int>(v);
            return true;
        }
        return notInteger(c, v, what);
    }
    bool notInteger(Cursor& c, double v, const char* what) const;
    bool gWord(Cursor& c) const;
    bool auxWord(Cursor& c) const;
    bool spindleWord(Cursor& c) const;
    bool scalarWord(Cursor& c) const;
    bool axisWord(Cursor& c) const;
    bool centerWord(Cursor& c) const;
    bool assignment(Cursor& c) const;
    bool machineDataAssignment(Cursor& c) const;
    bool jumpWord(Cursor& c) const;
    bool commandWord(Cursor& c) const;
    bool error(Cursor& c, const std::string& code, const std::string& message) const;

    const ProcessAxes& axes_;
    const AxisNameTable& names_;
    const ExpressionEvaluator& evaluator_;
};

}  // namespace mtc::core
