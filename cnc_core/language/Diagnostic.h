#pragma once

#include <string>
#include <vector>

namespace mtc::core {

enum class Severity { Warning, Error };

/// Where something happened: program number, block id ("N0012", "N0012:0001"
/// or "" for unnumbered blocks), 1-based source line and column (0 = unknown).
struct SourceLocation {
    int program = 0;
    std::string block;
    int line = 0;
    int column = 0;
};

/// A problem found in a program, a file or a run. Diagnostics are data: they
/// never throw across the cnc_core API. `code` is stable (tests and scripts key on it).
struct Diagnostic {
    Severity severity = Severity::Error;
    std::string code;
    SourceLocation where;
    std::string message;
    std::vector<std::string> details;
};

/// Collects diagnostics in the order they were found.
class DiagnosticList {
  public:
    void add(Diagnostic diagnostic) { items_.push_back(std::move(diagnostic)); }
    void error(std::string code, SourceLocation where, std::string message,
               std::vector<std::string> details = {}) {
        items_.push_back({Severity::Error, std::move(code), std::move(where), std::move(message),
                          std::move(details)});
    }
    void warning(std::string code, SourceLocation where, std::string message,
                 std::vector<std::string> details = {}) {
        items_.push_back({Severity::Warning, std::move(code), std::move(where), std::move(message),
                          std::move(details)});
    }
    void append(const DiagnosticList& other) {
        items_.insert(items_.end(), other.items_.begin(), other.items_.end());
    }
    bool hasErrors() const {
        for (const auto& d : items_)
            if (d.severity == Severity::Error) return true;
        return false;
    }
    bool empty() const { return items_.empty(); }
    std::size_t size() const { return items_.size(); }
    const std::vector<Diagnostic>& items() const { return items_; }
    void clear() { items_.clear(); }

  private:
    std::vector<Diagnostic> items_;
};

/// "error N0012 line 14: message" — one line for logs and the CLI's text output.
std::string formatDiagnostic(const Diagnostic& diagnostic);

}  // namespace mtc::core
