#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/language/Keywords.h"

namespace mtc::core {

/// A-Z only (names start with a capital letter).
inline bool isLetter(char c) {
    return c >= 'A' && c <= 'Z';
}

/// True for the operators after which a bracket opens a sub-expression.
inline bool isExpressionOperator(char c) {
    return c == '=' || c == '+' || c == '-' || c == '*' || c == '/';
}

/// True when `text` has '(' or '[' before `end`.
inline bool hasBracketBefore(std::string_view text, std::size_t end) {
    const std::string_view words = text.substr(0, end);
    return words.find('(') != std::string_view::npos || words.find('[') != std::string_view::npos;
}

/// forEachName for a text without brackets (and without its comment):
/// every name counts that starts with a letter and does not follow '.',
/// '*' or '@'.
template <typename Visit>
void forEachNameWithoutBrackets(std::string_view text, Visit visit) {
    std::size_t i = 0;
    while (i < text.size()) {
        if (!isNameChar(text[i])) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < text.size() && isNameChar(text[i]))
            ++i;
        const char before = start > 0 ? text[start - 1] : ' ';
        if (isLetter(text[start]) && before != '.' && before != '*' && before != '@')
            visit(start, i);
    }
}

/// forEachNameWithoutBrackets for only the names whose first letter c has
/// bit c - 'A' set in `letters`: the scan stops only at those letters and
/// skips the ones inside a run of name characters.
template <typename Visit>
void forEachNameWithoutBrackets(std::string_view text, std::uint32_t letters, Visit visit) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned letter = static_cast<unsigned char>(text[i]) - 'A';
        if (letter >= 26 || !((letters >> letter) & 1u)) continue;
        if (i > 0 && isNameChar(text[i - 1])) continue;  // inside a run
        const std::size_t start = i;
        while (i + 1 < text.size() && isNameChar(text[i + 1]))
            ++i;
        const char before = start > 0 ? text[start - 1] : ' ';
        if (before != '.' && before != '*' && before != '@') visit(start, i + 1);
    }
}

/// forEachName's general reading (any text, brackets tracked); forEachName
/// takes it for texts with brackets.
template <typename Visit>
void forEachNameAnyText(std::string_view text, Visit visit) {
    const std::size_t end = commentOffset(text);
    std::vector<bool> freeText;  // open brackets: true = a free text
    std::string_view lastName;   // the name before a bracket
    bool blankAfterName = false;
    char lastSignificant = ' ';  // the last character that is not a blank
    std::size_t i = 0;
    while (i < end) {
        const char c = text[i];
        if (c == '(' || c == '[') {
            const bool arguments =
                isExpressionOperator(lastSignificant) ||
                (!lastName.empty() &&
                 (!blankAfterName || lookupKeyword(lastName).keywordClass != KeywordClass::None));
            freeText.push_back(freeText.empty() ? !arguments : freeText.back());
            lastName = {};
            lastSignificant = c;
            ++i;
            continue;
        }
        if (!isNameChar(c)) {
            if (c == ')' || c == ']') {
                if (!freeText.empty()) freeText.pop_back();
                lastName = {};
            } else if (c == ' ') {
                blankAfterName = true;
            } else {
                lastName = {};
            }
            if (c != ' ') lastSignificant = c;
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < end && isNameChar(text[i]))
            ++i;
        const char before = start > 0 ? text[start - 1] : ' ';
        const bool inFreeText = !freeText.empty() && freeText.back();
        if (!inFreeText && isLetter(text[start]) && before != '.' && before != '*' && before != '@')
            visit(start, i);
        lastName = text.substr(start, i - start);
        blankAfterName = false;
        lastSignificant = text[i - 1];
    }
}

/// Calls `visit(begin, end)` for every name in `text` that may be a macro:
/// a run of A-Z 0-9 _ starting with a letter, not after '.', '*' or '@',
/// outside the comment and outside free texts (a bracket not directly
/// after a name, e.g. "(TOOL CHANGE)"); inside keyword arguments
/// ("MODF_ON(QUICK)", "MTD(...)") and inside the brackets of an expression
/// (after = + - * /: "L3_KORR = (D_SOLL - D_IST) /2", seed 001 ch. 4)
/// names count.
template <typename Visit>
void forEachName(std::string_view text, Visit visit) {
    const std::size_t end = commentOffset(text);
    if (hasBracketBefore(text, end))
        forEachNameAnyText(text, visit);
    else  // the common block: no free text, no arguments
        forEachNameWithoutBrackets(text.substr(0, end), visit);
}

/// forEachName for a visitor that only cares for names whose first letter c
/// has bit c - 'A' set in `letters` (it may be called for others too).
template <typename Visit>
void forEachNameStartingWith(std::string_view text, std::uint32_t letters, Visit visit) {
    const std::size_t end = commentOffset(text);
    if (hasBracketBefore(text, end))
        forEachNameAnyText(text, visit);
    else
        forEachNameWithoutBrackets(text.substr(0, end), letters, visit);
}

}  // namespace mtc::core
