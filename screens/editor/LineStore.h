#pragma once

#include <QString>
#include <cstddef>
#include <string>
#include <vector>

namespace mtc::screens {

/// The whole text of a large program as the windowed editor keeps it
/// (ED-009): one UTF-8 string plus the byte offset of every line. Lines are
/// separated by '\n' exactly as QTextDocument splits a plain text into
/// blocks ("a\nb\n" has three lines, the last one empty), so a window of
/// lines handed to a QTextDocument and read back with toPlainText() splices
/// in without changing anything outside it.
class LineStore {
  public:
    LineStore() = default;
    /// Takes the text (UTF-8) and indexes its lines.
    explicit LineStore(std::string text);

    /// Number of lines (at least 1: an empty text is one empty line).
    int count() const { return static_cast<int>(starts_.size()); }
    /// Lines first .. first+lines-1 joined by '\n' (no '\n' after the last).
    QString text(int first, int lines) const;
    /// The whole text (lines joined by '\n').
    const std::string& whole() const { return text_; }
    /// Replaces lines first .. first+lines-1 (lines >= 1) by the lines of
    /// `replacement` (split at '\n'; an empty replacement is one empty line).
    void replace(int first, int lines, const QString& replacement);

  private:
    std::size_t lineEnd(int line) const;

    std::string text_;
    std::vector<std::size_t> starts_{0};  ///< byte offset of each line
};

}  // namespace mtc::screens
