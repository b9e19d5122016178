#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cnc_core/language/Program.h"

namespace mtc::core {

/// Which blocks one program level can run through, read from the program
/// text (restart.md R-023): from the level's entry (N0000, a label, a start
/// block) the flow goes to the next block, and to the label of a branch in
/// the same program (conditional branches both ways, BRA only to its label);
/// a call (BSR, BEV, JSR, JEV) comes back to the next block; RTS, BST, RET,
/// JMP, M02, M30 and PROGRAMMENDE end the level. A skip block or a block with
/// errors may also fall through. This over-approximates what a run can do,
/// so a block it does not reach is never reached on that level: it belongs
/// to a subroutine (or is dead code).
///
/// Only the turning blocks (a jump word, M02 or M30: turnsFlow() in Word.h)
/// can lead anywhere but to the next block; the constructor takes them from
/// the words the program's WordList keeps as turning, and a query
/// runs straight from one turning block to the next over a bit set
/// (O(turning words * log blocks) once, then O(turning blocks + blocks / 64)
/// per query; docs/decisions/restart.md ).
class LevelReach {
  public:
    /// One bit per block, with the range operations of the straight walk.
    class BlockSet {
      public:
        explicit BlockSet(std::size_t size) : size_(size), bits_((size + 63) / 64, 0) {}
        std::size_t size() const { return size_; }
        bool test(std::size_t i) const { return (bits_[i / 64] >> (i % 64)) & 1u; }
        void set(std::size_t i) { bits_[i / 64] |= std::uint64_t{1} << (i % 64); }
        /// Sets [first, last).
        void setRange(std::size_t first, std::size_t last);
        /// The first set bit in [first, last); `last` when none.
        std::size_t findSet(std::size_t first, std::size_t last) const;

      private:
        std::size_t size_;
        std::vector<std::uint64_t> bits_;
    };

    explicit LevelReach(ProgramPtr program);

    /// True when the flow entered at one of `entries` can arrive at `block`.
    bool reaches(const std::vector<std::uint32_t>& entries, std::uint32_t block) const;
    /// Every block the flow entered at `entries` can arrive at.
    BlockSet reachable(const std::vector<std::uint32_t>& entries) const;
    /// The first RTS the program runs into when started at N0000 without a
    /// call: the straight flow from block 0 up to the first unconditional
    /// change of flow (BRA, JMP, BST, RET, RTS, M02, M30; within a block the
    /// first such word counts, and only a block's first jump word: a second
    /// is the error JUMP_TWICE). That RTS means a subroutine sits at the start
    /// of the program (seed 000, 2.4). Reads the turning blocks only.
    std::optional<std::uint32_t> returnWithoutCall() const;
    /// The subroutine of this program that runs through `block`: the label of a
    /// BSR / BEV of this program whose level reaches it, and the first block
    /// calling it. std::nullopt when no call of this program reaches it.
    struct Subroutine {
        std::string label;
        std::uint32_t labelBlock = 0;
        std::uint32_t callBlock = 0;
    };
    std::optional<Subroutine> subroutineOf(std::uint32_t block) const;

  private:
    /// Walks from `entries`; stops early when `stopAt` is reached. Fills `seen`.
    bool walk(const std::vector<std::uint32_t>& entries, BlockSet& seen,
              std::uint32_t stopAt) const;
    /// Blocks the flow may continue with after `block` (up to two).
    int successors(std::uint32_t block, std::uint32_t next[2]) const;
    /// The first turning block at or after `block`; blocks.size() when none.
    std::uint32_t nextTurning(std::uint32_t block) const;

    ProgramPtr program_;
    /// Blocks with a jump word or an M02 / M30, ascending: every other block
    /// goes on to the next one (and a PROGRAMMENDE block, always the last and
    /// without words, to none).
    std::vector<std::uint32_t> turning_;
};

}  // namespace mtc::core
