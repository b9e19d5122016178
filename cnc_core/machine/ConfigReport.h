#pragma once

#include <string>
#include <string_view>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/ConfigSchema.h"

namespace mtc::core {

/// Where a configuration reader is and how it tells about a problem: every
/// message names the file, the line (Diagnostic::where.line), the section,
/// the key, the value (quoted so that no raw byte reaches a terminal) and
/// the allowed range. After kMaxErrors errors it adds one CFG_TOO_MANY_ERRORS
/// and stays silent (a garbage file must not produce millions of lines).
class ConfigReport {
  public:
    static constexpr std::size_t kMaxErrors = 100;

    ConfigReport(std::string fileName, DiagnosticList& diagnostics)
        : file_(std::move(fileName)), diagnostics_(diagnostics) {}

    const std::string& file() const { return file_; }
    void setLine(int line) { line_ = line; }
    int line() const { return line_; }
    /// The section header the following lines belong to ("[process 0 axis X]").
    void setSection(std::string header) { section_ = std::move(header); }
    const std::string& section() const { return section_; }

    /// "<file>: [section] <key> = '<value>' <problem>; allowed: <range>" at the current line.
    void valueError(std::string_view code, std::string_view key, std::string_view value,
                    std::string_view problem, const ConfigRule* rule);
    /// "<file>: [section] <message>" at the current line.
    void error(std::string_view code, std::string_view message) { errorAt(line_, code, message); }
    /// "<file>: <message>" at `line` (0 = the file as a whole), no section.
    void errorAt(int line, std::string_view code, std::string_view message,
                 bool withSection = true);
    /// Adds `other` (diagnostics of checks over the whole cell) with the file named.
    void adopt(const DiagnosticList& other);
    /// True once the error limit was passed and said so (the reader may stop).
    bool full() const { return errors_ > kMaxErrors; }

  private:
    std::string file_;
    DiagnosticList& diagnostics_;
    int line_ = 0;
    std::string section_;
    std::size_t errors_ = 0;
};

}  // namespace mtc::core
