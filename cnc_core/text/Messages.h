#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/language/Diagnostic.h"

namespace mtc::core {

/// The languages a diagnostic can be shown in. The core writes every
/// message in English (the CLI's contract); German comes from the message
/// table (docs/DECISIONS.md D-023). The panel passes its language down as
/// this value: the core never asks Qt or the locale.
enum class Language { English, German };

/// "de", "de_DE", "de-AT" → German; "en", "en_GB", "C" → English; anything
/// else → nullopt.
std::optional<Language> languageFromTag(std::string_view tag);

/// The German brief message of a diagnostic code; empty when the table has
/// no row for it (a user compiler's own code, for instance).
std::string_view germanMessage(std::string_view code);

/// Every code of the table, in table order (for the completeness test).
std::vector<std::string_view> messageCodes();

/// A diagnostic as the operator reads it: a brief message and the lines of
/// its additional text.
struct DiagnosticText {
    std::string brief;
    std::vector<std::string> additional;
};

/// English: the core's message and details as they are. German: the
/// table's brief message for the code, and as additional text the core's
/// message (it names the values: word, axis, number, file) followed by the
/// details. A code without a German row keeps the English text.
DiagnosticText diagnosticText(const Diagnostic& diagnostic, Language language);

/// The diagnostic in one line, for the places without an additional text
/// (the alarm line, a screen's message line). English: the core's message.
/// German: the table's brief message, " — ", the core's English message
/// (its values); a code without a German row keeps the English message.
std::string messageLine(const Diagnostic& diagnostic, Language language);

/// An alarm, prompt or message the core raises without a diagnostic
/// ("Start refused: no program selected") under a stable code (ALARM_...,
/// PROMPT_..., MDI_...): German: the table's text for the code; English, or
/// a code without a row: `english` (docs/DECISIONS.md D-025). "%1" … "%9"
/// in the text chosen are replaced by `values` (D-026); a text without
/// values is returned as it is.
std::string alarmText(std::string_view code, const std::string& english, Language language,
                      const std::vector<std::string>& values = {});

/// `text` with "%1" … "%9" replaced by values[0] … values[8] in one pass (a
/// value that contains "%2" stays as it is); a "%" with no such value stays.
std::string fillIn(std::string_view text, const std::vector<std::string>& values);

/// "error" / "warning", or "Fehler" / "Warnung".
std::string severityWord(const Diagnostic& diagnostic, Language language);

/// formatDiagnostic() in `language`: the German frame ("Fehler [CODE]
/// Programm 5 N0010 Zeile 3:7: ") and messageLine() as the message, the
/// details as they are. English: formatDiagnostic() exactly (the CLI's text).
std::string formatDiagnostic(const Diagnostic& diagnostic, Language language);

}  // namespace mtc::core
