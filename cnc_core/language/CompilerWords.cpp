#include "cnc_core/language/CompilerWords.h"

#include <string>

namespace mtc::core {

bool findCompilerWord(const Program& program, Diagnostic& found) {
    if (!program.usesCompilerKeywords) return false;  // the parser saw none
    for (std::size_t b = 0; b < program.blocks.size(); ++b) {
        const Block block = program.blocks[b];
        for (std::uint32_t w = block.firstWord; w < block.firstWord + block.wordCount; ++w) {
            const Word word = program.words[w];
            if (!(word.flags & kWordNeedsCompiler)) continue;
            const std::string text(program.text(word.text));
            found = Diagnostic{Severity::Error,
                               "NEEDS_COMPILER",
                               {program.number, program.blockId(b), static_cast<int>(block.line),
                                static_cast<int>(word.column)},
                               "'" + text + "' is an NC compiler function; the program is refused",
                               {"The NC compiler is off (NC options: Compiler active = No), so "
                                "the control refuses the program when it is selected, as a "
                                "download would; switch the compiler on or remove the function."}};
            return true;
        }
    }
    return false;
}

}  // namespace mtc::core
