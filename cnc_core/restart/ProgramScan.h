#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "cnc_core/language/Program.h"

namespace mtc::core {

/// Fast look-ups over one parsed program for the NC program restart screen
/// (seed 000, 2.3-2.5): where a block is, where a text occurs, which blocks
/// are primary blocks. Built for programs of 1,000,000 blocks: every query is
/// O(log n) except the text search (one SSE2 pass over the source text) and
/// the one-time indexes, which are built on first use and kept.
class ProgramScan {
  public:
    /// Scans `program` (must not be null; kept alive by this object).
    explicit ProgramScan(ProgramPtr program);

    const ProgramPtr& program() const { return program_; }
    std::uint32_t blockCount() const { return static_cast<std::uint32_t>(program_->blocks.size()); }
    /// The block the <End> key goes to: the block before the end of the
    /// program (before PROGRAMMENDE), or the last block. O(1). 0 when empty.
    std::uint32_t lastSelectableBlock() const;
    /// The block whose text contains byte `offset` of the source, or the first
    /// block after it (comment lines belong to the next block); blockCount()
    /// when the offset lies after the last block. O(log n).
    std::uint32_t blockAtOffset(std::uint32_t offset) const;
    /// The block shown on 1-based source line `line`: the last block that
    /// starts on or before it (0 for lines before the first block). O(log n).
    std::uint32_t blockAtLine(std::uint32_t line) const;
    /// First block after `block` whose text, or the comment lines after
    /// `block`, contain `needle` (ASCII case-insensitive). Searches towards
    /// the end of the program only; std::nullopt when not found or `needle`
    /// is empty.
    std::optional<std::uint32_t> findTextAfter(std::uint32_t block, std::string_view needle) const;
    /// The last primary block (':') with index in [first, end), if any.
    /// The primary index is built on first use (one pass over the blocks).
    std::optional<std::uint32_t> lastPrimaryIn(std::uint32_t first, std::uint32_t end) const;
    /// True when the G word nearest before `block` among {`on`, `off`} is
    /// `on` (e.g. G91 still active against G90). Scans the source text
    /// backwards from the block and checks each hit against the block's words.
    bool modalActiveBefore(std::uint32_t block, int on, int off) const;

    /// Index of the first jump word (WordKind::Jump) of `block`, or -1.
    long jumpWordOf(std::uint32_t block) const;
    /// True when `block` has a G word with constant number `g`.
    bool hasG(std::uint32_t block, int g) const;

    /// Position of the first ASCII case-insensitive occurrence of `needle` in
    /// `haystack` at or after `from`; npos when none. Two-character SSE2 filter
    /// with a byte compare of the candidates.
    static std::size_t findFolded(std::string_view haystack, std::string_view needle,
                                  std::size_t from = 0);
    /// The same result; a text of at least `splitBytes` after `from` is cut
    /// in two halves searched at once, the second on a thread of its own
    /// (one core alone does not reach the memory bandwidth: a search through
    /// a 1,000,000-block program took 2.5-3 ms on one core).
    static std::size_t findFoldedSplit(std::string_view haystack, std::string_view needle,
                                       std::size_t from = 0,
                                       std::size_t splitBytes = kSplitSearchBytes);
    static constexpr std::size_t kSplitSearchBytes = std::size_t{4} << 20;

  private:
    ProgramPtr program_;
    mutable std::vector<std::uint32_t> primaries_;
    mutable bool primariesBuilt_ = false;
};

}  // namespace mtc::core
