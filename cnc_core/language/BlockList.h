#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cnc_core/language/Block.h"
#include "cnc_core/language/IndexIterator.h"
#include "cnc_core/support/PodArray.h"

namespace mtc::core {

/// Packed, append-mostly list of blocks (see the storage note in Program.h).
///
/// A block takes 12 bytes: its first word, source offset and line as 16-bit
/// deltas from the anchor of its group of kGroup blocks (one 12-byte Anchor
/// per group), its number, word count, text length (up to 255), flags and
/// line count. A block that does not fit (a label, comment, text or
/// sub-number, a longer text, a delta beyond 65535) is kept whole in
/// extended_, found by binary search over extendedIndex_. See
/// docs/decisions/language.md, "Memory".
class BlockList {
  public:
    using const_iterator = IndexIterator<BlockList, Block>;
    /// Number of blocks.
    std::size_t size() const { return packed_.size(); }
    bool empty() const { return packed_.empty(); }
    /// The block at `index` (by value). Precondition: index < size().
    const Block operator[](std::size_t index) const {
        Block block;
        read(index, block);
        return block;
    }
    /// Writes the block at `index` into `out` field by field. Inline, and
    /// without a temporary: the interpreter reads every block through it, and
    /// copying a freshly built Block stalls on store forwarding.
    void read(std::size_t index, Block& out) const {
        const Packed& p = packed_[index];
        if ((p.lineCount & kExtendedBit) && readExtended(index, out)) return;
        const Anchor& a = anchors_[index / kGroup];
        out.firstWord = a.firstWord + p.wordDelta;
        out.wordCount = p.wordCount;
        out.flags = p.flags;
        out.number = p.number;
        out.line = a.line + p.lineDelta;
        out.lineCount = p.lineCount & 0x7f;
        out.label = {};
        out.comment = {};
        out.sourceText = TextSpan{a.sourceOffset + p.sourceDelta, p.sourceLength};
        out.subNumber = -1;
        out.text = {};
    }
    const Block back() const { return (*this)[size() - 1]; }
    const Block front() const { return (*this)[0]; }
    const_iterator begin() const;
    const_iterator end() const;
    /// Appends `block`.
    void push_back(const Block& block);
    /// Appends a one-line block with a number of N0000..N9999 or none (-1),
    /// no flags, label, comment, text or sub-number (the parser's fast path
    /// for whole lines), as push_back would. Appends nothing and returns false
    /// when its text is longer than 65535 bytes; the caller then appends a
    /// full Block.
    bool tryPushPlain(std::uint32_t firstWord, std::uint16_t wordCount, std::int16_t number,
                      std::uint32_t line, std::uint32_t sourceOffset, std::uint32_t sourceLength) {
        if (sourceLength > 65535) return false;
        const std::uint32_t wordDelta = firstWord - group_.firstWord;
        const std::uint32_t sourceDelta = sourceOffset - group_.sourceOffset;
        const std::uint32_t lineDelta = line - group_.line;
        const auto inGroup = static_cast<std::uint32_t>(packed_.size()) - groupFirst_;  // 1..64
        // One test for the rare cases: 16-bit deltas, 8-bit length and word
        // count, and a block that starts a group (inGroup == kGroup).
        if ((wordDelta | sourceDelta | lineDelta | ((sourceLength | wordCount) << 8) |
             (inGroup << 10)) > 0xffff) {
            pushPlainWhole(firstWord, wordCount, number, line, sourceOffset, sourceLength);
            return true;
        }
        // Field stores into the element itself, as WordList::tryPushNumber.
        Packed& p = packed_.emplace_back();
        p.wordDelta = static_cast<std::uint16_t>(wordDelta);
        p.sourceDelta = static_cast<std::uint16_t>(sourceDelta);
        p.lineDelta = static_cast<std::uint16_t>(lineDelta);
        p.number = number;
        p.wordCount = static_cast<std::uint8_t>(wordCount);
        p.sourceLength = static_cast<std::uint8_t>(sourceLength);
        p.flags = 0;
        p.lineCount = 1;
        return true;
    }
    /// Replaces the block at `index`. Precondition: index < size().
    void set(std::size_t index, const Block& block);
    /// N number of block `index` without unpacking the rest (fast path).
    std::int32_t numberAt(std::size_t index) const;
    /// Reserves room for `count` blocks (no effect on the contents).
    void reserve(std::size_t count) {
        packed_.reserve(count);
        anchors_.reserve(count / kGroup + 1);
    }
    /// Drops unused capacity (only when worthwhile).
    void shrink_to_fit();
    /// Removes every block.
    void clear();
    /// Bytes held (for memory measurements).
    std::size_t memoryBytes() const;

  private:
    static constexpr std::uint8_t kExtendedBit = 0x80;
    /// Blocks per anchor.
    static constexpr std::uint32_t kGroup = 64;
    static_assert(kGroup << 10 > 0xffff && (kGroup - 1) << 10 <= 0xffff, "see tryPushPlain");
    /// Where a group of kGroup blocks starts: the first block's word,
    /// source offset and line (its Packed deltas are 0).
    struct Anchor {
        std::uint32_t firstWord;
        std::uint32_t sourceOffset;
        std::uint32_t line;
    };
    /// A block as the deltas from its group's anchor.
    struct Packed {
        std::uint16_t wordDelta;    ///< firstWord - anchor
        std::uint16_t sourceDelta;  ///< sourceText.offset - anchor
        std::uint16_t lineDelta;    ///< line - anchor
        std::int16_t number;
        std::uint8_t wordCount;
        std::uint8_t sourceLength;
        std::uint8_t flags;
        std::uint8_t lineCount;  ///< 1..127, bit 7 = extended (full Block in extended_)
    };
    /// The packed form of `block` at `index` in `p`; false when it has none.
    bool pack(const Block& block, std::size_t index, Packed& p) const;
    /// Appends the anchor of a new group when `block` starts one.
    void anchorFor(const Block& block);
    /// Appends `block` after its anchor is in place.
    void append(const Block& block);
    /// tryPushPlain's block through push_back (out of line): the first of
    /// a group, or one without a packed form.
    void pushPlainWhole(std::uint32_t firstWord, std::uint16_t wordCount, std::int16_t number,
                        std::uint32_t line, std::uint32_t sourceOffset, std::uint32_t sourceLength);
    long findExtended(std::size_t index) const;
    /// The block at `index` kept whole (labels, comments, long lines) into
    /// `out`; false when it has no whole copy (then the packed form holds it).
    bool readExtended(std::size_t index, Block& out) const;
    PodArray<Packed> packed_;                   // large: huge pages
    PodArray<Anchor> anchors_;                  ///< one per kGroup blocks
    Anchor group_{};                            ///< anchors_.back() (or zeros)
    std::uint32_t groupFirst_ = 0 - kGroup;     ///< index of group_'s first block
    std::vector<std::uint32_t> extendedIndex_;  ///< sorted block indices
    std::vector<Block> extended_;
};

inline BlockList::const_iterator BlockList::begin() const {
    return {this, 0};
}
inline BlockList::const_iterator BlockList::end() const {
    return {this, size()};
}

}  // namespace mtc::core
