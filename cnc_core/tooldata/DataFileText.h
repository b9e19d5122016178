#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/language/Diagnostic.h"

namespace mtc::core {

/// The line reader and strict value rules shared by the tool list and zero
/// offset files (docs/TOOL-DATA.md): one record per line, `#` comments, a
/// `format = <name> 1` line first and an `end = <records>` line last (a
/// file cut off anywhere is refused), `[process N]` sections. Every
/// refusal names file, line, key, value and the allowed range.
class DataFileText {
  public:
    /// `file` is only used in messages.
    DataFileText(std::string file, DiagnosticList& diagnostics, std::string code)
        : file_(std::move(file)), diagnostics_(diagnostics), code_(std::move(code)) {}

    /// An error at `line` about `key` = `value`: "FILE:LINE: key 'K' = 'V': PROBLEM".
    void refuse(int line, const std::string& key, const std::string& value,
                const std::string& problem);
    /// An error at `line` that concerns no key.
    void refuseLine(int line, const std::string& problem);

    /// A decimal number (optional sign, digits, optional fraction and
    /// exponent; no hex, inf, nan, comma) inside [low, high]; otherwise a
    /// refusal that names the range in `unit`.
    bool number(int line, const std::string& key, const std::string& value, double low, double high,
                const char* unit, double& out);
    /// An integer inside [low, high].
    bool integer(int line, const std::string& key, const std::string& value, long long low,
                 long long high, long long& out);

    bool failed() const { return failed_; }
    const std::string& file() const { return file_; }

  private:
    std::string file_;
    DiagnosticList& diagnostics_;
    std::string code_;
    bool failed_ = false;
};

/// The text without leading and trailing blanks, tabs and CR.
std::string_view trimmedText(std::string_view text);
/// Splits at blanks and tabs.
std::vector<std::string_view> wordsOf(std::string_view text);
/// A number as the files write it: the shortest text that reads back the same.
std::string formatDataNumber(double value);

}  // namespace mtc::core

namespace mtc::core {

/// Reads the frame every data file shares and hands each record line to
/// `record(line, process, text)`: comments and blank lines skipped; first
/// `format = <formatName> 1`; `[process N]` (0..6, each once) before any
/// record; last `end = <number of records>`, nothing after it. Returns
/// false when the frame or a record was refused (`out` has the reasons).
/// `section(process)` is called for every `[process N]`.
bool readDataFrame(std::string_view text, std::string_view formatName, DataFileText& out,
                   const std::function<void(int line, int process, std::string_view text)>& record,
                   const std::function<void(int process)>& section = {});

/// The frame's first line, "format = <formatName> 1\n".
std::string dataFrameHeader(std::string_view formatName);

}  // namespace mtc::core
