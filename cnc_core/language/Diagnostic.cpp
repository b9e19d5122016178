#include "cnc_core/language/Diagnostic.h"

namespace mtc::core {

std::string formatDiagnostic(const Diagnostic& d) {
    std::string text = d.severity == Severity::Error ? "error" : "warning";
    text += " [" + d.code + "]";
    if (d.where.program != 0) text += " program " + std::to_string(d.where.program);
    if (!d.where.block.empty()) text += " " + d.where.block;
    if (d.where.line > 0) {
        text += " line " + std::to_string(d.where.line);
        if (d.where.column > 0) text += ":" + std::to_string(d.where.column);
    }
    text += ": " + d.message;
    for (const auto& detail : d.details)
        text += "\n    " + detail;
    return text;
}

}  // namespace mtc::core
