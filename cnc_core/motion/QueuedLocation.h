#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

#include "cnc_core/language/Diagnostic.h"

namespace mtc::core::motion {

/// Where a queue entry comes from, as the SourceLocation it was queued with,
/// without a std::string per entry (docs/decisions/motion.md MOT-027): the
/// block id ("N0012", "N0012:0001", "": at most 22 characters) is kept in
/// place, so queueing an entry and finishing it copy a few words instead of
/// assigning a string twice. A longer text (no block id is one) is shared
/// and comes back the same.
class QueuedLocation {
  public:
    /// Takes program, block text, line and column of `where`.
    void assign(const SourceLocation& where) {
        program_ = where.program;
        line_ = where.line;
        column_ = where.column;
        const std::size_t size = where.block.size();
        if (size > kInline) return assignLong(where.block);
        std::memcpy(text_.data(), where.block.data(), size);
        size_ = static_cast<std::uint8_t>(size);
        if (long_) long_.reset();
    }
    /// The SourceLocation it was assigned, field for field.
    SourceLocation location() const;
    int program() const { return program_; }
    int line() const { return line_; }
    /// Same program and line: the same block (a block may queue several
    /// entries: an inserted corner arc and its line, an M function and a
    /// move; single block tells blocks apart by them).
    bool sameBlock(const QueuedLocation& other) const {
        return program_ == other.program_ && line_ == other.line_;
    }

  private:
    void assignLong(const std::string& text);

    static constexpr std::size_t kInline = 22;
    /// size_ of a text longer than kInline: it is in long_.
    static constexpr std::uint8_t kLong = 0xff;

    int program_ = 0;
    int line_ = 0;
    int column_ = 0;
    std::uint8_t size_ = 0;
    std::array<char, kInline> text_{};
    std::shared_ptr<const std::string> long_;  ///< only for a text longer than kInline
};

}  // namespace mtc::core::motion
