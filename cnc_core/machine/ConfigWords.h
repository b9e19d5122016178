#pragma once

#include <string_view>
#include <vector>

/// Splitting of configuration lines into words and fields, without copies
/// (the views point into the text given).
namespace mtc::core {

/// `text` without leading and trailing blanks, tabs and carriage returns.
inline std::string_view trimConfigText(std::string_view text) {
    std::size_t begin = 0, end = text.size();
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (begin < end && blank(text[begin]))
        ++begin;
    while (end > begin && blank(text[end - 1]))
        --end;
    return text.substr(begin, end - begin);
}

/// The blank- or tab-separated words of `text` (none for blank text).
inline std::vector<std::string_view> splitConfigWords(std::string_view text) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t'))
            ++i;
        const std::size_t start = i;
        while (i < text.size() && text[i] != ' ' && text[i] != '\t')
            ++i;
        if (i > start) words.push_back(text.substr(start, i - start));
    }
    return words;
}

/// Every `separator`-separated field of `text`, trimmed; empty fields are
/// kept (so "a||b" has three fields).
inline std::vector<std::string_view> splitConfigFields(std::string_view text, char separator) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    for (;;) {
        const std::size_t end = text.find(separator, start);
        fields.push_back(trimConfigText(text.substr(start, end - start)));
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    return fields;
}

}  // namespace mtc::core
