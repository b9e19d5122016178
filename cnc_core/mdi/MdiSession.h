#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "cnc_core/compiler/CompilerTypes.h"
#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/Program.h"
#include "cnc_core/text/Messages.h"

namespace mtc::core {

/// One MDI entry the station ran (or tried to run), newest last.
struct MdiHistoryItem {
    std::string text;  ///< the input as typed
    /// "running", "done", "error line 2: ...", "reset" (German: D-026)
    std::string outcome;
};

/// Manual data input of one station (docs/decisions/mdi.md): the input the
/// operator types, the history of entries, the message for the operator,
/// and the program Start runs in MDI mode. The station owns it; the MDI
/// screen only edits the input and renders the rest. The input is never
/// lost: only an entry that ran to its end unchanged is cleared (MDI-004).
class MdiSession {
  public:
    /// History entries kept (oldest dropped first).
    static constexpr std::size_t kMaxHistory = 50;

    const std::string& input() const { return input_; }
    void setInput(std::string text) { input_ = std::move(text); }
    /// Puts history item `row` back into the input (false: no such item).
    bool recall(std::size_t row);
    const std::deque<MdiHistoryItem>& history() const { return history_; }
    /// The last message for the operator (in the language) and whether it
    /// is an error.
    const std::string& message() const { return message_; }
    bool messageIsError() const { return messageIsError_; }
    /// The language of the messages, the history's outcomes and the alarm
    /// texts built from a diagnostic (the panel's; English by default,
    /// docs/DECISIONS.md D-024, D-026).
    void setLanguage(Language language) { language_ = language; }

    /// Checks the input (macros, keywords, syntax) without running it; the
    /// result is message(), the refusals go to `diagnostics`. True when
    /// Start could run it.
    bool check(const std::vector<MacroDefinition>& globals, DiagnosticList& diagnostics);
    /// For Start in MDI mode: the entry's program, or "" with the refusal's
    /// diagnostics in `diagnostics` and the alarm text returned.
    std::string take(const std::vector<MacroDefinition>& globals, ProgramPtr& program,
                     DiagnosticList& diagnostics);
    /// The entry that ran ended: `completed` false after a reset, the run's
    /// diagnostics (lines = input lines) get the input line as detail.
    void ended(bool completed, DiagnosticList& diagnostics);
    /// Adds "MDI input line N: <text>" to a diagnostic of `input` that names
    /// an input line and has no such detail yet.
    static void attachInputLine(Diagnostic& diagnostic, const std::string& input);

  private:
    void setMessage(std::string text, bool error);
    /// The text of `code` in the language, values filled in (alarmText()).
    std::string text(const char* code, const char* english,
                     const std::vector<std::string>& values = {}) const;
    std::string runningOutcome() const;
    std::string cannotRun() const;
    /// The first error's one-line text for the message line.
    void reportRefusal(const DiagnosticList& diagnostics);

    std::string input_;
    std::string running_;  ///< text of the entry that runs ("" = none)
    std::deque<MdiHistoryItem> history_;
    std::string message_;
    bool messageIsError_ = false;
    Language language_ = Language::English;
};

}  // namespace mtc::core
