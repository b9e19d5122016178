#include "cnc_core/language/CompilerWords.h"

#include <algorithm>
#include <string>

namespace mtc::core {

bool findCompilerWord(const Program& program, Diagnostic& found) {
    if (!program.usesCompilerKeywords) return false;  // the parser saw none
    for (std::size_t b = 0; b < program.blocks.size(); ++b) {
        const Block block = program.blocks[b];
        for (std::uint32_t w = block.firstWord; w < block.firstWord + block.wordCount; ++w) {
            const Word word = program.words[w];
            if (!(word.flags & kWordNeedsCompiler)) continue;
            // the keyword itself (a macro use holds the rest of its block)
            std::string text(program.text(word.text));
            text = text.substr(0, std::min<std::size_t>(text.find(' '), 24));
            // one line: the panel shows it as the station's alarm
            found =
                Diagnostic{Severity::Error,
                           "NEEDS_COMPILER",
                           {program.number, program.blockId(b), static_cast<int>(block.line),
                            static_cast<int>(word.column)},
                           "'" + text + "' needs the NC compiler, which is off: program refused",
                           {}};
            return true;
        }
    }
    return false;
}

}  // namespace mtc::core
