#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cnc_core/language/Block.h"
#include "cnc_core/language/IndexIterator.h"
#include "cnc_core/support/LargeAllocator.h"

namespace mtc::core {

/// Packed, append-mostly list of blocks (see the storage note at the top).
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
        out.firstWord = p.firstWord;
        out.wordCount = p.wordCount;
        out.flags = p.flags;
        out.number = p.number;
        out.line = p.line;
        out.lineCount = p.lineCount & 0x7f;
        out.label = {};
        out.comment = {};
        out.sourceText = TextSpan{p.sourceOffset, p.sourceLength};
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
        // Field stores into the element itself, as WordList::tryPushNumber.
        Packed& p = packed_.emplace_back();
        p.firstWord = firstWord;
        p.sourceOffset = sourceOffset;
        p.line = line;
        p.number = number;
        p.wordCount = wordCount;
        p.sourceLength = static_cast<std::uint16_t>(sourceLength);
        p.flags = 0;
        p.lineCount = 1;
        return true;
    }
    /// Replaces the block at `index`. Precondition: index < size().
    void set(std::size_t index, const Block& block);
    /// N number of block `index` without unpacking the rest (fast path).
    std::int32_t numberAt(std::size_t index) const;
    /// Reserves room for `count` blocks (no effect on the contents).
    void reserve(std::size_t count) { packed_.reserve(count); }
    /// Drops unused capacity (only when worthwhile).
    void shrink_to_fit();
    /// Removes every block.
    void clear();
    /// Bytes held (for memory measurements).
    std::size_t memoryBytes() const;

  private:
    static constexpr std::uint8_t kExtendedBit = 0x80;
    struct Packed {
        std::uint32_t firstWord;
        std::uint32_t sourceOffset;
        std::uint32_t line;
        std::int16_t number;
        std::uint16_t wordCount;
        std::uint16_t sourceLength;
        std::uint8_t flags;
        std::uint8_t lineCount;  ///< 1..127, bit 7 = extended (full Block in extended_)
    };
    static bool packable(const Block& block);
    Packed pack(const Block& block) const;
    long findExtended(std::size_t index) const;
    /// The block at `index` kept whole (labels, comments, long lines) into
    /// `out`; false when it has no whole copy (then the packed form holds it).
    bool readExtended(std::size_t index, Block& out) const;
    std::vector<Packed, LargeAllocator<Packed>> packed_;  // large: huge pages
    std::vector<std::uint32_t> extendedIndex_;            ///< sorted block indices
    std::vector<Block> extended_;
};

inline BlockList::const_iterator BlockList::begin() const {
    return {this, 0};
}
inline BlockList::const_iterator BlockList::end() const {
    return {this, size()};
}

}  // namespace mtc::core
