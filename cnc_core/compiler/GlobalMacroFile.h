#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/compiler/CompilerTypes.h"

/// The global macros of the "NC options" (seed 001, ch. 4): checking a
/// definition, the file that keeps them in the program directory, and the
/// expansion of an MDI line. Decisions: docs/decisions/global-macros.md.
namespace mtc::core {

/// Name of the global macro file in the program directory.
inline constexpr const char* kGlobalMacroFileName = "GLOBAL_MACROS.MAC";
/// Seed 001 ch. 4: a global macro's instructions have at most 156 characters.
inline constexpr std::size_t kMaxGlobalMacroBodyLength = 156;

/// One line of the macro file that was not taken (1-based line, reason).
struct MacroFileProblem {
    int line = 0;
    std::string message;
};

/// Result of reading a macro file: the macros taken (in file order) and the
/// lines refused.
struct MacroFileContents {
    std::vector<MacroDefinition> macros;
    std::vector<MacroFileProblem> problems;
};

/// Problem with `candidate` as a global macro beside `others` ("" = fine):
/// name (letter first, A-Z 0-9 _, <= 20 characters, no keyword), name not
/// yet used, instructions present, <= 156 characters, one line, no comment,
/// no DEFINE, and no nesting in either direction (its instructions use no
/// other macro and no other macro's instructions use its name).
/// `replacing` is the name being changed ("" when adding).
std::string checkGlobalMacro(const MacroDefinition& candidate,
                             const std::vector<MacroDefinition>& others,
                             std::string_view replacing = {});

/// Reads the text of a macro file: one `DEFINE name AS instructions` a
/// line; blank lines and lines starting with ';' are ignored. A line that
/// does not pass checkGlobalMacro() is refused with its line number, the
/// others are kept. Never throws.
MacroFileContents parseGlobalMacroFile(std::string_view text);
/// The text of a macro file holding `macros` (parseGlobalMacroFile() reads
/// it back unchanged).
std::string formatGlobalMacroFile(const std::vector<MacroDefinition>& macros);

/// Reads `<directory>/GLOBAL_MACROS.MAC`; a missing file is no macro and no
/// problem, an unreadable one is a problem at line 0.
MacroFileContents readGlobalMacroFile(const std::string& directory);
/// Writes `macros` to `<directory>/GLOBAL_MACROS.MAC` atomically; false with
/// `error` when the file was not replaced.
bool writeGlobalMacroFile(const std::string& directory, const std::vector<MacroDefinition>& macros,
                          std::string& error);

/// An MDI line with the global macros expanded (seed 001 ch. 4 and ch. 12:
/// the graphical panel allows global macros in MDI, no other compiler
/// keyword). False with `problem` when the line defines a macro or uses a
/// compiler keyword (before or after expansion).
bool expandMdiLine(const std::string& line, const std::vector<MacroDefinition>& globals,
                   std::string& expanded, std::string& problem);

}  // namespace mtc::core
