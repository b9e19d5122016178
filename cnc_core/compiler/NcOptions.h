#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/compiler/CompilerTypes.h"
#include "cnc_core/compiler/UserCompilers.h"

/// The NC options of the cell (seed 001 ch. 4, 7, 8): "Compiler active",
/// the four user-related compiler commands and the global macros, with the
/// settings file that keeps them in the program directory. The global macros
/// stay in GLOBAL_MACROS.MAC (GlobalMacroFile.h). Decisions:
/// docs/decisions/nc-options.md (NO-001..).
namespace mtc::core {

/// Name of the settings file in the program directory (NO-002).
inline constexpr const char* kNcOptionsFileName = "NC_OPTIONS.CFG";
/// Longest user compiler command accepted (NO-003).
inline constexpr std::size_t kMaxUserCompilerCommandLength = 200;
/// Number of user-related compiler slots (seed 001 ch. 8: 1, 2 before and
/// 3, 4 after the INDRAMAT compiler).
inline constexpr int kUserCompilerSlotCount = 4;

/// Everything the NC options menu holds.
struct NcOptions {
    bool compilerActive = false;  ///< preset No (seed 001 ch. 7)
    UserCompilerSlots userCompilers;
    std::vector<MacroDefinition> globalMacros;
};

/// One line of an NC options file that was not taken.
struct NcOptionsProblem {
    std::string file;  ///< file name (NC_OPTIONS.CFG or GLOBAL_MACROS.MAC)
    int line = 0;      ///< 1-based, 0 = the file as a whole
    std::string message;
};

/// Result of reading the NC options: what was taken and what was refused.
struct NcOptionsContents {
    NcOptions options;
    std::vector<NcOptionsProblem> problems;
};

/// The command of user compiler `slot` (1..4); slots outside give "".
const std::string& userCompilerCommand(const UserCompilerSlots& slots, int slot);
/// Sets the command of user compiler `slot` (1..4); false for another slot.
bool setUserCompilerCommand(UserCompilerSlots& slots, int slot, std::string command);

/// Problem with `command` as a user compiler command ("" = fine; an empty
/// command empties the slot): one line, no control characters, at most
/// kMaxUserCompilerCommandLength characters, no leading or trailing blank.
std::string checkUserCompilerCommand(std::string_view command);

/// Reads one `DEFINE name AS instructions` entry typed by the operator and
/// checks it beside `others` (checkGlobalMacro; `replacing` = the name
/// being changed). False with `problem` when it is not taken.
bool parseGlobalMacroEntry(std::string_view line, const std::vector<MacroDefinition>& others,
                           std::string_view replacing, MacroDefinition& macro,
                           std::string& problem);

/// Reads the text of NC_OPTIONS.CFG: `KEY = value` lines (COMPILER_ACTIVE
/// = YES|NO, USER_COMPILER_1..4 = command); blank lines and lines starting
/// with ';' are ignored. A bad line (unknown key, bad value, key given
/// twice) is refused with its line number, the setting keeps its preset.
/// The result has no global macros. Never throws.
NcOptionsContents parseNcOptionsFile(std::string_view text);
/// The text of NC_OPTIONS.CFG for `options` (its global macros are not in
/// it); parseNcOptionsFile() reads it back unchanged.
std::string formatNcOptionsFile(const NcOptions& options);

/// Reads NC_OPTIONS.CFG and GLOBAL_MACROS.MAC of `directory`; missing files
/// give the presets, refused lines are listed with their file.
NcOptionsContents readNcOptions(const std::string& directory);
/// Writes `<directory>/NC_OPTIONS.CFG` for `options` atomically; false with
/// `error` when the file was not replaced.
bool writeNcOptionsFile(const std::string& directory, const NcOptions& options, std::string& error);

}  // namespace mtc::core
