#include "cnc_core/text/Messages.h"

#include "cnc_core/text/MessageTables.h"

namespace mtc::core {

namespace {

using messages::MessageTable;

std::vector<MessageTable> allTables() {
    return {messages::programMessages(), messages::compilerMessages(), messages::setupMessages(),
            messages::alarmMessages()};
}

}  // namespace

std::optional<Language> languageFromTag(std::string_view tag) {
    const std::string_view base = tag.substr(0, tag.find_first_of("_-.@"));
    if (base == "de") return Language::German;
    if (base == "en" || base == "C" || base == "POSIX") return Language::English;
    return std::nullopt;
}

std::string_view germanMessage(std::string_view code) {
    // A linear search: a few hundred rows, looked up only when a message is shown.
    for (const MessageTable& table : allTables())
        for (std::size_t i = 0; i < table.size; ++i)
            if (code == table.entries[i].code) return table.entries[i].german;
    return {};
}

std::vector<std::string_view> messageCodes() {
    std::vector<std::string_view> codes;
    for (const MessageTable& table : allTables())
        for (std::size_t i = 0; i < table.size; ++i)
            codes.emplace_back(table.entries[i].code);
    return codes;
}

DiagnosticText diagnosticText(const Diagnostic& diagnostic, Language language) {
    const std::string_view german =
        language == Language::German ? germanMessage(diagnostic.code) : std::string_view{};
    if (german.empty()) return {diagnostic.message, diagnostic.details};
    DiagnosticText text{std::string(german), {}};
    if (!diagnostic.message.empty()) text.additional.push_back(diagnostic.message);
    for (const std::string& detail : diagnostic.details)  // no line twice
        if (detail != diagnostic.message) text.additional.push_back(detail);
    return text;
}

std::string messageLine(const Diagnostic& diagnostic, Language language) {
    const std::string_view german =
        language == Language::German ? germanMessage(diagnostic.code) : std::string_view{};
    if (german.empty()) return diagnostic.message;
    std::string line(german);
    if (!diagnostic.message.empty()) line += " — " + diagnostic.message;
    return line;
}

std::string alarmText(std::string_view code, const std::string& english, Language language,
                      const std::vector<std::string>& values) {
    const std::string_view german =
        language == Language::German ? germanMessage(code) : std::string_view{};
    const std::string_view text = german.empty() ? std::string_view(english) : german;
    return values.empty() ? std::string(text) : fillIn(text, values);
}

std::string fillIn(std::string_view text, const std::vector<std::string>& values) {
    std::string filled;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const std::size_t index =
            i + 1 < text.size() ? static_cast<std::size_t>(text[i + 1] - '1') : values.size();
        if (text[i] == '%' && index < values.size() && index < 9) {
            filled += values[index];
            ++i;
        } else {
            filled += text[i];
        }
    }
    return filled;
}

std::string severityWord(const Diagnostic& diagnostic, Language language) {
    const bool error = diagnostic.severity == Severity::Error;
    if (language == Language::German) return error ? "Fehler" : "Warnung";
    return error ? "error" : "warning";
}

std::string formatDiagnostic(const Diagnostic& d, Language language) {
    if (language == Language::English) return formatDiagnostic(d);
    std::string text = severityWord(d, language) + " [" + d.code + "]";
    if (d.where.program != 0) text += " Programm " + std::to_string(d.where.program);
    if (!d.where.block.empty()) text += " " + d.where.block;
    if (d.where.line > 0) {
        text += " Zeile " + std::to_string(d.where.line);
        if (d.where.column > 0) text += ":" + std::to_string(d.where.column);
    }
    text += ": " + messageLine(d, language);
    for (const auto& detail : d.details)
        text += "\n    " + detail;
    return text;
}

}  // namespace mtc::core
