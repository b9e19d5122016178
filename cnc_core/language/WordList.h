#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cnc_core/language/IndexIterator.h"
#include "cnc_core/language/Word.h"
#include "cnc_core/support/PodArray.h"

namespace mtc::core {

/// Packed, append-mostly list of words (see the storage note at the top).
class WordList {
  public:
    using const_iterator = IndexIterator<WordList, Word>;
    /// Largest column the 8-byte form holds.
    static constexpr std::uint32_t kMaxPackedColumn = 255;
    /// The 8-byte form of a word.
    struct Packed {
        std::uint8_t kind;
        std::uint8_t letter;
        std::uint8_t bits;     ///< axisIndex (2) | scale (3) << 2 | extended << 5
        std::uint8_t column;   ///< 1..255
        std::int32_t payload;  ///< mantissa, or index into extended_
    };
    /// Number of words.
    std::size_t size() const { return packed_.size(); }
    bool empty() const { return packed_.empty(); }
    /// The word at `index` (by value). Precondition: index < size().
    const Word operator[](std::size_t index) const {
        Word word;
        read(index, word);
        return word;
    }
    /// Writes the word at `index` into `out` field by field. Inline, and
    /// without a temporary: the interpreter reads every word of every block
    /// through it, and copying a freshly built Word stalls on store forwarding.
    void read(std::size_t index, Word& out) const {
        const Packed& p = packed_[index];
        if (p.bits & kExtendedBit) {
            out = extended_[static_cast<std::size_t>(p.payload)];
            return;
        }
        out.kind = static_cast<WordKind>(p.kind);
        out.letter = static_cast<char>(p.letter);
        out.axisIndex = p.bits & 3u;
        out.jump = JumpKind::BRA;
        out.column = p.column;
        out.expr = -1;
        out.target = -1;
        const unsigned scale = (p.bits >> 2) & 7u;
        // Most words are integers (G1, Y0, F1000): skip the slow division.
        out.number = scale == 0 ? static_cast<double>(p.payload)
                                : static_cast<double>(p.payload) / kPow10[scale];
        out.text = {};
        out.eventProcess = -1;
        out.eventNumber = -1;
        out.flags = 0;
        out.args = {};
    }
    /// The word at `index` when the 8-byte form holds it (a plain number such
    /// as G1, X10.5 or F1000: no expression, text or event) into `out`
    /// (`expr` = -1); false for any other word, which read() gives whole.
    /// The interpreter decodes through it without building a Word.
    bool readNumber(std::size_t index, NumberWord& out) const {
        const Packed& p = packed_[index];
        if (p.bits & kExtendedBit) return false;
        out.kind = static_cast<WordKind>(p.kind);
        out.letter = static_cast<char>(p.letter);
        out.axisIndex = p.bits & 3u;
        out.column = p.column;
        out.expr = -1;
        const unsigned scale = (p.bits >> 2) & 7u;
        out.number = scale == 0 ? static_cast<double>(p.payload)
                                : static_cast<double>(p.payload) / kPow10[scale];
        return true;
    }
    const Word back() const { return (*this)[size() - 1]; }
    const Word front() const { return (*this)[0]; }
    const_iterator begin() const;
    const_iterator end() const;
    /// Appends `word`; picks the 8-byte form when the word allows it.
    void push_back(const Word& word);
    /// Appends a plain numeric word, value = mantissa / 10^scale, in the 8-byte
    /// form (the parser's fast path). Appends nothing and returns false when
    /// it does not fit (scale > 7, |mantissa| >= 2^31, column 0 or > 255,
    /// axisIndex > 3); the caller then appends a full Word.
    bool tryPushNumber(WordKind kind, char letter, std::uint8_t axisIndex, std::uint32_t column,
                       std::int64_t mantissa, unsigned scale) {
        if (scale >= 8 || column < 1 || column > kMaxPackedColumn || axisIndex > 3 ||
            mantissa > 2147483647 || mantissa < -2147483647)
            return false;
        // Field stores into the element itself: building a temporary and
        // copying it stalls on store forwarding in this hot path.
        Packed& p = packed_.emplace_back();
        p.kind = static_cast<std::uint8_t>(kind);
        p.letter = static_cast<std::uint8_t>(letter);
        p.bits = static_cast<std::uint8_t>(axisIndex | (scale << 2));
        p.column = static_cast<std::uint8_t>(column);
        p.payload = static_cast<std::int32_t>(mantissa);
        return true;
    }
    /// The form tryPushNumber stores for a word it takes for sure: no axis
    /// index, column 1..kMaxPackedColumn, |mantissa| < 2^31, scale < 8.
    static Packed smallNumber(WordKind kind, char letter, std::uint32_t column,
                              std::int32_t mantissa, unsigned scale) {
        return Packed{static_cast<std::uint8_t>(kind), static_cast<std::uint8_t>(letter),
                      static_cast<std::uint8_t>(scale << 2), static_cast<std::uint8_t>(column),
                      mantissa};
    }
    /// Appending in place (the parser's fast path): the free slots after the
    /// last word are [spareBegin(), spareEnd()); write words of smallNumber()
    /// there, then endAt(the slot after the last one written). makeSpare()
    /// makes room for one more word when there is none, as push_back would.
    Packed* spareBegin() { return packed_.spareBegin(); }
    Packed* spareEnd() { return packed_.spareEnd(); }
    void endAt(const Packed* end) { packed_.endAt(end); }
    void makeSpare() { packed_.makeSpare(); }
    /// Drops the words from `count` on. Precondition: count <= size(), and
    /// every word dropped was appended by tryPushNumber.
    void truncate(std::size_t count) { packed_.resize(count); }
    /// Replaces the word at `index`. Precondition: index < size().
    void set(std::size_t index, const Word& word);
    /// Reserves room for `count` words (no effect on the contents).
    void reserve(std::size_t count) { packed_.reserve(count); }
    /// Drops unused capacity (only when worthwhile).
    void shrink_to_fit();
    /// Removes every word.
    void clear();
    /// Bytes held (for memory measurements).
    std::size_t memoryBytes() const;

  private:
    static constexpr double kPow10[8] = {1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6, 1e7};
    static constexpr std::uint8_t kExtendedBit = 1u << 5;
    static bool packable(const Word& word, std::int32_t& mantissa, unsigned& scale);
    Packed pack(const Word& word);
    PodArray<Packed> packed_;  // large: huge pages
    std::vector<Word> extended_;
};

inline WordList::const_iterator WordList::begin() const {
    return {this, 0};
}
inline WordList::const_iterator WordList::end() const {
    return {this, size()};
}

}  // namespace mtc::core
