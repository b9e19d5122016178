#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "cnc_core/compiler/CompilerTypes.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/Program.h"
#include "cnc_core/machine/ProcessControl.h"
#include "cnc_core/text/Messages.h"

/// Manual data input (MDI): the NC blocks an operator types at the panel and
/// starts in MDI mode. Seed 001 ch. 4 and ch. 12: in the graphical panel the
/// global macros of the NC options may be used, no other compiler keyword.
/// Decisions: docs/decisions/mdi.md (MDI-001 ..).
namespace mtc::core {

/// Title of the transient program an MDI entry becomes. Its number is 0 (no
/// program of the store has it), so diagnostics name no program.
inline constexpr const char* kMdiProgramName = "MDI";
/// Most lines (blocks) one MDI entry may have (MDI-003).
inline constexpr std::size_t kMaxMdiLines = 20;
/// Most characters of one MDI line (MDI-003).
inline constexpr std::size_t kMaxMdiLineLength = 240;

/// What an MDI input becomes: its lines as typed, the lines with the global
/// macros expanded, and the parsed program (nullptr when the input was
/// refused). Every diagnostic's `where.line` is the 1-based line of the
/// input; a diagnostic from here is always of MDI origin.
struct MdiEntry {
    std::string input;
    std::vector<std::string> lines;
    std::vector<std::string> expanded;
    ProgramPtr program;
    DiagnosticList diagnostics;
    /// True when the entry can run (a program and no error).
    bool runnable() const { return program && !diagnostics.hasErrors(); }
};

/// The MDI input `input` (one block a line; blank and comment-only lines are
/// allowed) checked, its global macros `globals` expanded line by line
/// (expandMdiLine) and parsed into a transient program. Refusals: nothing to
/// run (MDI_EMPTY), too many or too long lines (MDI_TOO_LONG), a macro
/// definition or a compiler keyword (MDI_KEYWORD_REFUSED), parse errors
/// (the parser's codes). Never throws.
MdiEntry prepareMdiEntry(const std::string& input, const std::vector<MacroDefinition>& globals);

/// Why the station refuses to run an MDI entry now ("" = it may): not in MDI
/// mode, or a program is active; in the station's language (D-026).
std::string mdiRefusal(const ProcessControl& control);

/// "MDI input line 2: G1 X5": the additional text that names an input line.
std::string mdiInputDetail(int line, const std::string& text);

/// "MDI line 2: error [CODE]: message" — one diagnostic of an MDI entry for
/// the alarm line and logs (details on further lines). German: "MDI Zeile 2:
/// Fehler [CODE]: " and messageLine() (docs/DECISIONS.md D-024).
std::string formatMdiDiagnostic(const Diagnostic& diagnostic,
                                Language language = Language::English);

}  // namespace mtc::core
