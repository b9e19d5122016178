#include "cnc_core/text/Messages.h"

#include "cnc_core/text/MessageTables.h"

namespace mtc::core {

namespace {

using messages::MessageTable;

std::vector<MessageTable> allTables() {
    return {messages::programMessages(), messages::compilerMessages(), messages::setupMessages()};
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

}  // namespace mtc::core
