#pragma once

#include <string>
#include <vector>

#include "cnc_core/compiler/Compiler.h"

namespace mtc::test {

/// Compiles `source` with the standard passes and the compiler active.
inline core::CompileResult compileText(const std::string& source,
                                       std::vector<core::MacroDefinition> globals = {}) {
    core::CompilerOptions options;
    options.compilerActive = true;
    options.programNumber = 1;
    options.globalMacros = std::move(globals);
    return core::Compiler().compile(source, options);
}

/// The object text's block lines ("N0001:0000 ...") without identification,
/// header and continuation lines.
inline std::vector<std::string> objectBlocks(const core::CompileResult& result) {
    std::vector<std::string> lines;
    std::size_t start = 0, index = 0;
    const std::string& text = result.objectText;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (index < result.lineMap.size() &&
            result.lineMap[index].kind == core::ObjectLineKind::Block)
            lines.push_back(text.substr(start, end - start));
        start = end + 1;
        ++index;
    }
    return lines;
}

/// Codes of the result's messages in order.
inline std::vector<std::string> codes(const core::CompileResult& result) {
    std::vector<std::string> out;
    for (const core::CompilerError& e : result.errors)
        out.push_back(e.code);
    return out;
}

}  // namespace mtc::test
