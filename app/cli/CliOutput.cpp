#include "cli/CliOutput.h"

namespace mtc::cli {

const char* severityName(core::Severity severity) {
    return severity == core::Severity::Error ? "error" : "warning";
}

void writeDiagnosticJson(JsonWriter& json, const core::Diagnostic& d) {
    json.beginObject();
    json.field("severity", severityName(d.severity));
    json.field("code", d.code);
    json.field("program", d.where.program);
    json.field("block", d.where.block);
    json.field("line", d.where.line);
    json.field("column", d.where.column);
    json.field("message", d.message);
    json.key("details");
    json.beginArray();
    for (const std::string& detail : d.details)
        json.value(detail);
    json.endArray();
    json.endObject();
}

void writeDiagnosticsJson(JsonWriter& json, const core::DiagnosticList& diagnostics) {
    json.key("diagnostics");
    json.beginArray();
    for (const core::Diagnostic& d : diagnostics.items())
        writeDiagnosticJson(json, d);
    json.endArray();
}

void printDiagnosticsText(std::FILE* stream, const core::DiagnosticList& diagnostics) {
    for (const core::Diagnostic& d : diagnostics.items())
        std::fprintf(stream, "%s\n", core::formatDiagnostic(d).c_str());
}

int exitCodeFor(bool fileProblem, const core::DiagnosticList& diagnostics) {
    if (fileProblem) return 2;
    return diagnostics.hasErrors() ? 1 : 0;
}

void beginStatusDocument(JsonWriter& json, const char* status) {
    json.beginObject();
    json.field("status", status);
}

void endDocumentWithDiagnostics(JsonWriter& json, const core::DiagnosticList& diagnostics) {
    writeDiagnosticsJson(json, diagnostics);
    json.endObject();
    json.finish();
}

void printRefusedDiagnostics(const core::DiagnosticList& diagnostics) {
    for (const core::Diagnostic& d : diagnostics.items())
        std::fprintf(stderr, "mtc200-cli: %s\n", core::formatDiagnostic(d).c_str());
}

int reportUsageError(const std::string& message, bool json) {
    std::fprintf(stderr, "mtc200-cli: %s\n(mtc200-cli --help lists commands and options)\n",
                 message.c_str());
    if (json) {
        core::DiagnosticList diagnostics;
        diagnostics.error("CLI_USAGE", {}, message);
        return reportSetupFailure(diagnostics, true);
    }
    return 2;
}

int reportSetupFailure(const core::DiagnosticList& diagnostics, bool json) {
    if (!json) {
        printRefusedDiagnostics(diagnostics);
        return 2;
    }
    JsonWriter writer(stdout);
    beginStatusDocument(writer, "error");
    endDocumentWithDiagnostics(writer, diagnostics);
    return 2;
}

}  // namespace mtc::cli
