#include "cnc_core/machine/ConfigReport.h"

#include "cnc_core/machine/ConfigText.h"

namespace mtc::core {

void ConfigReport::valueError(std::string_view code, std::string_view key, std::string_view value,
                              std::string_view problem, const ConfigRule* rule) {
    std::string message = std::string(key) + " = " + quotedValue(value) + " " +
                          std::string(problem);
    if (rule) message += "; allowed: " + configRangeText(*rule);
    error(code, message);
}

void ConfigReport::errorAt(int line, std::string_view code, std::string_view message,
                           bool withSection) {
    if (errors_ > kMaxErrors) return;
    if (errors_++ == kMaxErrors) {
        diagnostics_.error("CFG_TOO_MANY_ERRORS", {0, "", line, 0},
                           file_ + ": more than " + std::to_string(kMaxErrors) +
                               " errors; the rest of the file is not reported");
        return;
    }
    std::string text = file_ + ": ";
    if (withSection && !section_.empty()) text += section_ + " ";
    text += message;
    diagnostics_.error(std::string(code), {0, "", line, 0}, std::move(text));
}

void ConfigReport::adopt(const DiagnosticList& other) {
    for (const Diagnostic& d : other.items()) {
        if (d.severity == Severity::Error) {
            errorAt(d.where.line, d.code, d.message, false);
            continue;
        }
        Diagnostic copy = d;
        copy.message = file_ + ": " + copy.message;
        diagnostics_.add(std::move(copy));
    }
}

}  // namespace mtc::core
