#pragma once

#include <string_view>

/// Line-oriented settings files of the NC options (GLOBAL_MACROS.MAC,
/// NC_OPTIONS.CFG): the same trimming and comment rule for both.
namespace mtc::core {

/// `text` without blanks and tabs at both ends (and a CR of a CRLF line end).
inline std::string_view trimmedSettingText(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
        text.remove_suffix(1);
    return text;
}

/// Calls `take(lineNumber, line)` (1-based, trimmed) for every line of
/// `text` that is neither blank nor a comment starting with ';'.
template <class Take>
void forEachSettingLine(std::string_view text, Take take) {
    int lineNumber = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = trimmedSettingText(text.substr(pos, end - pos));
        ++lineNumber;
        pos = end + 1;
        if (!line.empty() && line.front() != ';') take(lineNumber, line);
    }
}

}  // namespace mtc::core
