#pragma once

#include <cstdio>
#include <string>

#include "cli/JsonWriter.h"
#include "cnc_core/language/Diagnostic.h"

namespace mtc::cli {

/// "error" or "warning".
const char* severityName(core::Severity severity);

/// Writes one diagnostic as the contract's JSON object (severity, code,
/// program, block, line, column, message, details).
void writeDiagnosticJson(JsonWriter& json, const core::Diagnostic& diagnostic);

/// Writes `"diagnostics": [...]` (key and array) into the open object.
void writeDiagnosticsJson(JsonWriter& json, const core::DiagnosticList& diagnostics);

/// Opens the document object of a command and writes its "status" member
/// ("ok" / "error") first, as every command's JSON starts.
void beginStatusDocument(JsonWriter& json, const char* status);
/// Writes the "diagnostics" member last, closes the document object and ends
/// the document.
void endDocumentWithDiagnostics(JsonWriter& json, const core::DiagnosticList& diagnostics);
/// Prints every diagnostic as "mtc200-cli: <diagnostic>" to stderr (refusals
/// and setup failures in text mode).
void printRefusedDiagnostics(const core::DiagnosticList& diagnostics);

/// Prints every diagnostic as one readable line (plus detail lines) to `stream`.
void printDiagnosticsText(std::FILE* stream, const core::DiagnosticList& diagnostics);

/// Exit code for a finished command: 2 on a file/usage problem, 1 on errors
/// in programs or runs, 0 otherwise.
int exitCodeFor(bool fileProblem, const core::DiagnosticList& diagnostics);

/// Reports a usage error: message and hint on stderr; with --json also the one
/// JSON document {"status":"error","diagnostics":[CLI_USAGE]} on stdout.
/// Returns exit code 2.
int reportUsageError(const std::string& message, bool json);

/// Reports file or configuration problems that stop a command before it ran:
/// the diagnostics on stderr (text) or as the JSON document on stdout.
/// Returns exit code 2.
int reportSetupFailure(const core::DiagnosticList& diagnostics, bool json);

}  // namespace mtc::cli
