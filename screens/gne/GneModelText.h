#pragma once

// A text of the GNE editing model for the operator. The model is plain C++
// and speaks English; its forms are marked for Qt Linguist where they are
// written (QT_TRANSLATE_NOOP("GneModel", ...)), and the screen shows them
// in the panel's language (screens/gne/GneTexts.h, docs/DECISIONS.md D-018).

#include <string>
#include <utility>
#include <vector>

namespace mtc::screens::gnefields {

/// An English form with %1..%9 for the values it names ("%1 must be
/// given"), and those values. When `diagnosticCode` is set, the last value
/// is the core's English message of a GNE diagnostic with that code; the
/// screen adds the code's German brief message in German (D-023).
struct ModelText {
    ModelText() = default;
    ModelText(const char* text, std::vector<std::string> values = {}, std::string code = {})
        : form(text), args(std::move(values)), diagnosticCode(std::move(code)) {}

    const char* form = "";
    std::vector<std::string> args;
    std::string diagnosticCode;

    bool empty() const { return *form == '\0'; }
    /// The form with the values filled in.
    std::string english() const;
};

/// Each text's english(), one per line.
std::string englishLines(const std::vector<ModelText>& texts);

}  // namespace mtc::screens::gnefields
