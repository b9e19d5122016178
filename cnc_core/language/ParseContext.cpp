#include "cnc_core/language/ParseContext.h"

#include <algorithm>
#include <cstdio>

namespace mtc::core {

void ParseContext::report(Severity severity, const char* code, std::uint32_t line,
                          std::uint32_t column, std::string block, std::string message) {
    ++reported_;
    if (reported_ > kMaxDiagnostics + 1) return;
    SourceLocation where{program_.number, std::move(block), static_cast<int>(line),
                         static_cast<int>(column)};
    if (reported_ == kMaxDiagnostics + 1) {
        program_.diagnostics.error("PARSE_TOO_MANY_DIAGNOSTICS", where,
                                   "more than 1000 problems; the rest are not listed");
        return;
    }
    program_.diagnostics.add(Diagnostic{severity, code, std::move(where), std::move(message), {}});
}

void ParseContext::addMacro(std::string_view name) {
    macros_.emplace_back(name);
    shortestMacro_ = std::min(shortestMacro_, name.size());
    longestMacro_ = std::max(longestMacro_, name.size());
    const unsigned letter = name.empty() ? 0 : static_cast<unsigned char>(name[0]) - 'A';
    if (letter < 26) macroLetters_ |= 1u << letter;
}

bool ParseContext::findMacro(std::string_view name) const {
    for (const auto& macro : macros_)  // the length first: most names differ in it
        if (macro.size() == name.size() && std::string_view(macro) == name) return true;
    return false;
}

std::string formatBlockId(std::int32_t number, std::int32_t subNumber) {
    if (number < 0) return {};
    char buffer[32];
    if (subNumber >= 0)
        std::snprintf(buffer, sizeof buffer, "N%04d:%04d", number, subNumber);
    else
        std::snprintf(buffer, sizeof buffer, "N%04d", number);
    return buffer;
}

}  // namespace mtc::core
