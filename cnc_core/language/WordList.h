#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "cnc_core/language/IndexIterator.h"
#include "cnc_core/language/Word.h"
#include "cnc_core/support/PodArray.h"
#include "cnc_core/text/Decimal.h"

namespace mtc::core {

/// Packed, append-mostly list of words (see the storage note in Program.h).
///
/// Every word has one 4-byte slot and one column byte (columns_, same
/// index). A narrow slot holds a plain numeric word whole: in its low 5 bits
/// a code for its head (kind, letter, axis index, decimal scale; up to
/// kHeadCount heads per list, in heads_), in the top 27 bits the mantissa
/// (|m| < 2^26: 67,108.863 at three decimals): value = mantissa / 10^scale;
/// its column is the column byte. A slot with the code kWideCode is wide:
/// its upper 27 bits index an 8-byte Wide form in wide_ (a plain word with a
/// 32-bit mantissa, or a reference to the whole Word in extended_); one with
/// kExtendedCode indexes the whole Word in extended_ directly. See
/// docs/decisions/language.md, "Memory".
class WordList {
  public:
    using const_iterator = IndexIterator<WordList, Word>;
    WordList() { forgetHeads(); }
    /// Largest column a packed form holds.
    static constexpr std::uint32_t kMaxPackedColumn = 255;
    /// One slot (see the class note).
    using Packed = std::uint32_t;
    /// Number of words.
    std::size_t size() const { return slots_.size(); }
    bool empty() const { return slots_.empty(); }
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
        const Packed slot = slots_[index];
        const Packed code = slot & kCodeMask;
        if (code >= kExtendedCode) {
            if (code == kExtendedCode)
                out = extended_[slot >> kWideShift];
            else
                readWide(index, slot, out);
            return;
        }
        // kind, letter, axisIndex and jump (BRA = 0) in one load and store:
        // the head's scale byte lies where the word's jump goes.
        std::uint32_t head = 0;
        std::memcpy(&head, &heads_[code], sizeof head);
        const std::uint32_t front = head & 0x00ffffffu;
        std::memcpy(static_cast<void*>(&out), &front, sizeof front);
        out.column = columns_[index];
        out.expr = -1;
        out.target = -1;
        out.number = valueOf(narrowMantissa(slot), head >> 24);
        out.text = {};
        out.eventProcess = -1;
        out.eventNumber = -1;
        out.flags = 0;
        out.args = {};
    }
    /// The word at `index` when a packed form holds it (a plain number such
    /// as G1, X10.5 or F1000: no expression, text or event) into `out`
    /// (`expr` = -1); false for any other word, which read() gives whole.
    /// The interpreter decodes through it without building a Word.
    bool readNumber(std::size_t index, NumberWord& out) const {
        const Packed slot = slots_[index];
        const Packed code = slot & kCodeMask;
        if (code < kExtendedCode) {
            // Field by field (and no call that is given `out`), so that a
            // caller may keep `out` in registers.
            const Head& head = heads_[code];
            if (head.axisIndex > 3) __builtin_unreachable();  // no head has more
            out.kind = head.kind;
            out.letter = head.letter;
            out.axisIndex = head.axisIndex;
            out.column = columns_[index];
            out.expr = -1;
            out.number = valueOf(narrowMantissa(slot), head.scale);
            return true;
        }
        if (code == kExtendedCode) return false;
        const Wide& wide = wideAt(index, slot);
        if (wide.bits & kExtendedBit) return false;
        setNumber(out, wideHead(wide), wide.column, wide.payload);
        return true;
    }
    /// The kind of the word at `index` alone, without its value or column:
    /// whole-program scans (restart, compiler) that look for a few kinds read
    /// every other word through it. Precondition: index < size().
    WordKind kindAt(std::size_t index) const {
        const Packed slot = slots_[index];
        const Packed code = slot & kCodeMask;
        return code < kExtendedCode ? heads_[code].kind : wholeKind(index, slot);
    }
    /// The index of every word for which turnsFlow() holds, ascending: every
    /// change of the list keeps it (the parser's fast path through
    /// noteFlowTurning()). The restart's flow analysis reads the turning
    /// blocks from it instead of scanning every word (restart.md R-037).
    const std::vector<std::uint32_t>& flowTurningWords() const { return turning_; }
    /// turnsFlow() of the plain number mantissa / 10^scale (no expression);
    /// the value is worked out for an M word only (the only kind it decides).
    static bool numberTurnsFlow(WordKind kind, std::int32_t mantissa, unsigned scale) {
        if (kind != WordKind::M) return turnsFlow(kind, -1, 0.0);
        return endsProgram(kind, -1, valueOf(mantissa, scale));
    }
    const Word back() const { return (*this)[size() - 1]; }
    const Word front() const { return (*this)[0]; }
    const_iterator begin() const;
    const_iterator end() const;
    /// Appends `word`; picks the smallest form the word allows.
    void push_back(const Word& word);
    /// Appends a plain numeric word, value = mantissa / 10^scale, in a packed
    /// form (the parser's fast path). Appends nothing and returns false when
    /// it does not fit (scale > 7, |mantissa| >= 2^31, column 0 or > 255,
    /// axisIndex > 3); the caller then appends a full Word.
    bool tryPushNumber(WordKind kind, char letter, std::uint8_t axisIndex, std::uint32_t column,
                       std::int64_t mantissa, unsigned scale);
    /// Narrow slots of the parser's fast path (its words have no axis index
    /// and the kind addressKind(letter) gives; letters 'A'..'Z'):
    /// plainCodeAt(codeKey(letter, scale)) is the head code of such a word,
    /// or kWideCode when none is known yet; plainCode() then finds or makes
    /// it (kWideCode when the head table is full). The slot is
    /// narrowSlot(code, mantissa) for |mantissa| < kNarrowLimit.
    static constexpr Packed kWideCode = 31;
    static constexpr std::uint32_t kNarrowLimit = std::uint32_t{1} << 26;
    /// Precondition: '@' <= letter <= '_', scale < 8.
    static std::size_t codeKey(unsigned letter, unsigned scale) {
        return (letter - 0x40u) * 8 + scale;  // one lea
    }
    Packed plainCodeAt(std::size_t key) const { return plainCodes_[key]; }
    Packed plainCode(WordKind kind, char letter, unsigned scale);
    static Packed narrowSlot(Packed code, std::int32_t mantissa) {
        return code | (static_cast<Packed>(mantissa) << kMantissaShift);
    }
    /// Appending in place (the parser's fast path): the free slots after the
    /// last word are [spareBegin(), spareEnd()), their column bytes from
    /// spareColumns() on (spareColumns()[k] belongs to spareBegin()[k]);
    /// write slots of narrowSlot() and their columns (1..kMaxPackedColumn)
    /// there, then endAt(the slot after the last one written). makeSpare()
    /// makes room for one more word when there is none, as push_back would.
    /// A slot whose word numberTurnsFlow() must be noted with
    /// noteFlowTurning(slot) before endAt().
    Packed* spareBegin() { return slots_.spareBegin(); }
    Packed* spareEnd() { return slots_.data() + std::min(slots_.capacity(), columns_.capacity()); }
    std::uint8_t* spareColumns() { return columns_.spareBegin(); }
    void endAt(const Packed* end) {
        slots_.endAt(end);
        columns_.endAt(columns_.data() + slots_.size());
    }
    void makeSpare() {
        slots_.makeSpare();
        columns_.reserve(slots_.capacity());
    }
    void noteFlowTurning(const Packed* slot);
    /// Drops the words from `count` on. Precondition: count <= size(), and
    /// every word dropped was appended by tryPushNumber or as a narrowSlot().
    void truncate(std::size_t count);
    /// Replaces the word at `index`. Precondition: index < size().
    void set(std::size_t index, const Word& word);
    /// Reserves room for `count` words (no effect on the contents).
    void reserve(std::size_t count) {
        slots_.reserve(count);
        columns_.reserve(count);
    }
    /// Drops unused capacity (only when worthwhile).
    void shrink_to_fit();
    /// Removes every word.
    void clear();
    /// Bytes held (for memory measurements).
    std::size_t memoryBytes() const;

  private:
    /// The head of a narrow word: all of it but column and mantissa; laid
    /// out as the first four bytes of a Word, with the scale for the jump.
    struct Head {
        WordKind kind;
        char letter;
        std::uint8_t axisIndex;
        std::uint8_t scale;
        bool operator==(const Head& other) const {  // one 4-byte compare
            std::uint32_t a = 0, b = 0;
            std::memcpy(&a, this, sizeof a);
            std::memcpy(&b, &other, sizeof b);
            return a == b;
        }
    };
    /// The 8-byte form of a word that has no narrow one.
    struct Wide {
        std::uint8_t kind;
        std::uint8_t letter;
        std::uint8_t bits;     ///< axisIndex (2) | scale (3) << 2 | extended << 5
        std::uint8_t column;   ///< 1..255
        std::int32_t payload;  ///< mantissa, or index into extended_
    };
    static constexpr Packed kCodeMask = 31;
    static constexpr unsigned kMantissaShift = 5;
    static constexpr unsigned kMantissaBits = 32 - kMantissaShift;
    static constexpr std::uint32_t kMantissaLimit = std::uint32_t{1} << (kMantissaBits - 1);
    /// A slot of a word kept whole: this code and the index into extended_.
    static constexpr Packed kExtendedCode = kWideCode - 1;
    static constexpr unsigned kHeadCount = kExtendedCode;
    /// A wide slot: kWideCode and the index into wide_ above it.
    static constexpr unsigned kWideShift = kMantissaShift;
    /// Wide slots from this index on are found in overflow_ (by word index).
    static constexpr Packed kOverflowIndex = (Packed{1} << (32 - kWideShift)) - 1;
    static constexpr std::uint8_t kExtendedBit = 1u << 5;

    static std::size_t cacheKey(char letter, unsigned scale) {
        return (static_cast<std::size_t>(static_cast<unsigned char>(letter) & 31u) << 3) | scale;
    }
    /// The value mantissa / 10^scale of every packed form.
    static double valueOf(std::int32_t mantissa, unsigned scale) {
        // Most words are integers (G1, Y0, F1000): skip the slow division.
        return scale == 0 ? static_cast<double>(mantissa) : exactDecimal(mantissa, scale);
    }
    /// Fills `out` from a head (its bytes: kind, letter, axis index, scale).
    static void setNumber(NumberWord& out, std::uint32_t head, std::uint16_t column,
                          std::int32_t mantissa) {
        out.kind = static_cast<WordKind>(head & 0xffu);
        out.letter = static_cast<char>((head >> 8) & 0xffu);
        out.axisIndex = static_cast<std::uint8_t>((head >> 16) & 3u);  // never more than 3
        out.column = column;
        out.expr = -1;
        out.number = valueOf(mantissa, head >> 24);
    }
    /// The top kMantissaBits bits of a narrow slot, sign-extended.
    static std::int32_t narrowMantissa(Packed slot) {
        return static_cast<std::int32_t>(slot) >> kMantissaShift;
    }
    /// The code of `head`: a new one when there is room, else kWideCode.
    /// An empty cache entry holds kWideCode, whose head matches no word.
    unsigned codeFor(const Head& head) {
        const std::size_t key = cacheKey(head.letter, head.scale);
        const unsigned code = codeCache_[key];
        return heads_[code] == head ? code : codeOf(head, key);
    }
    /// codeFor() when the cache under `key` misses.
    unsigned codeOf(const Head& head, std::size_t key);
    /// Empties the head table and its cache.
    void forgetHeads();
    static bool packable(const Word& word, std::int32_t& mantissa, unsigned& scale);
    /// The column byte of `word` (0 for a column beyond kMaxPackedColumn).
    static std::uint8_t columnByte(const Word& word);
    /// The slot for `word` at a new wide index when it needs one.
    Packed pack(const Word& word, std::size_t index);
    Packed packNumber(WordKind kind, char letter, std::uint8_t axisIndex, std::uint32_t column,
                      std::int32_t mantissa, unsigned scale, std::size_t index);
    Packed addWide(const Wide& wide, std::size_t index);
    const Wide& wideAt(std::size_t index, Packed slot) const;
    Wide& wideAt(std::size_t index, Packed slot);
    void readWide(std::size_t index, Packed slot, Word& out) const;
    /// Lists or unlists word `index` in turning_ (set()).
    void noteTurning(std::size_t index, bool turns);
    /// kindAt() of a wide or extended slot.
    WordKind wholeKind(std::size_t index, Packed slot) const;
    /// The head (as setNumber() takes it) of a plain wide form.
    static std::uint32_t wideHead(const Wide& wide) {
        return wide.kind | (std::uint32_t{wide.letter} << 8) |
               (std::uint32_t{wide.bits & 3u} << 16) | (std::uint32_t{(wide.bits >> 2) & 7u} << 24);
    }

    static_assert(offsetof(Word, kind) == 0 && offsetof(Word, letter) == 1 &&
                      offsetof(Word, axisIndex) == 2 && offsetof(Word, jump) == 3 &&
                      sizeof(Head) == 4 && static_cast<int>(JumpKind::BRA) == 0,
                  "read() copies a Head over the first four bytes of a Word");
    static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
                  "readNumber() takes a Head's fields from its bytes in a 32-bit value");
    /// The heads in use: [0, headCount_); heads_[kWideCode] matches no word.
    /// First, so that reading a head needs no offset.
    Head heads_[kWideCode + 1] = {};
    PodArray<Packed> slots_;          // large: huge pages
    PodArray<std::uint8_t> columns_;  ///< the column of every word (0 when > 255)
    std::vector<Wide> wide_;
    std::vector<std::pair<std::uint32_t, Wide>> overflow_;  ///< by word index, sorted
    std::vector<Word> extended_;
    std::vector<std::uint32_t> turning_;  ///< see flowTurningWords()
    unsigned headCount_ = 0;
    std::uint8_t codeCache_[32 * 8] = {};  ///< code by letter and scale (a hint)
    Packed plainCodes_[32 * 8] = {};       ///< see plainCodeAt()
};

inline bool WordList::tryPushNumber(WordKind kind, char letter, std::uint8_t axisIndex,
                                    std::uint32_t column, std::int64_t mantissa, unsigned scale) {
    if (scale >= 8 || column < 1 || column > kMaxPackedColumn || axisIndex > 3 ||
        mantissa > 2147483647 || mantissa < -2147483647)
        return false;
    const std::size_t index = slots_.size();
    const Packed slot = packNumber(kind, letter, axisIndex, column,
                                   static_cast<std::int32_t>(mantissa), scale, index);
    if (numberTurnsFlow(kind, static_cast<std::int32_t>(mantissa), scale))
        turning_.push_back(static_cast<std::uint32_t>(index));
    slots_.push_back(slot);
    columns_.push_back(static_cast<std::uint8_t>(column));
    return true;
}

inline WordList::const_iterator WordList::begin() const {
    return {this, 0};
}
inline WordList::const_iterator WordList::end() const {
    return {this, size()};
}

}  // namespace mtc::core
