#include "cli/CliOutput.h"

namespace mtc::cli {

const char* severityName(core::Severity severity) {
    return severity == core::Severity::Error ? "error" : "warning";
}

void writeDiagnosticJson(JsonWriter& json, const core::Diagnostic& d) {
    json.beginObject();
    json.key("severity");
    json.value(severityName(d.severity));
    json.key("code");
    json.value(d.code);
    json.key("program");
    json.value(d.where.program);
    json.key("block");
    json.value(d.where.block);
    json.key("line");
    json.value(d.where.line);
    json.key("column");
    json.value(d.where.column);
    json.key("message");
    json.value(d.message);
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

int reportUsageError(const std::string& message, bool json) {
    std::fprintf(stderr, "mtc200-cli: %s\n(mtc200-cli --help lists commands and options)\n",
                 message.c_str());
    if (json) {
        core::DiagnosticList diagnostics;
        diagnostics.error("CLI_USAGE", {}, message);
        JsonWriter writer(stdout);
        writer.beginObject();
        writer.key("status");
        writer.value("error");
        writeDiagnosticsJson(writer, diagnostics);
        writer.endObject();
        writer.finish();
    }
    return 2;
}

int reportSetupFailure(const core::DiagnosticList& diagnostics, bool json) {
    if (!json) {
        for (const core::Diagnostic& d : diagnostics.items())
            std::fprintf(stderr, "mtc200-cli: %s\n", core::formatDiagnostic(d).c_str());
        return 2;
    }
    JsonWriter writer(stdout);
    writer.beginObject();
    writer.key("status");
    writer.value("error");
    writeDiagnosticsJson(writer, diagnostics);
    writer.endObject();
    writer.finish();
    return 2;
}

}  // namespace mtc::cli
