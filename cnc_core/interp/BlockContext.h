#pragma once

#include <string>
#include <vector>

#include "cnc_core/interp/BlockDecoder.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/Program.h"

namespace mtc::core {

/// The block being checked and where its diagnostics go.
struct BlockContext {
    const Program& program;
    std::uint32_t blockIndex;
    DiagnosticList& diagnostics;

    /// Adds an error at `column` of the block; always returns false.
    bool error(const std::string& code, const std::string& message, int column = 0,
               std::vector<std::string> details = {}) const {
        diagnostics.error(code, blockLocation(program, blockIndex, column), message,
                          std::move(details));
        return false;
    }
    /// Adds a warning at `column` of the block.
    void warning(const std::string& code, const std::string& message, int column = 0) const {
        diagnostics.warning(code, blockLocation(program, blockIndex, column), message);
    }
};

}  // namespace mtc::core
