#include "cnc_core/language/WordList.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>

namespace mtc::core {

namespace {

/// Finds the overflow entry of word `index` (sorted by word index).
template <typename Entries>
auto findOverflow(Entries& entries, std::size_t index) {
    return std::lower_bound(
        entries.begin(), entries.end(), index,
        [](const auto& entry, std::size_t wanted) { return entry.first < wanted; });
}

}  // namespace

bool WordList::packable(const Word& word, std::int32_t& mantissa, unsigned& scale) {
    if (word.kind >= WordKind::Assign || word.expr >= 0 || word.target >= 0 ||
        word.text.length != 0 || word.args.length != 0 || word.eventProcess != -1 ||
        word.eventNumber != -1 || word.flags != 0 || word.axisIndex > 3 || word.column == 0 ||
        word.column > kMaxPackedColumn || !std::isfinite(word.number))
        return false;
    for (scale = 0; scale < 8; ++scale) {
        double scaled = std::nearbyint(word.number * kPowersOfTen[scale]);
        if (std::fabs(scaled) > 2147483647.0) return false;
        if (scaled / kPowersOfTen[scale] == word.number &&
            !(scaled == 0.0 && std::signbit(word.number))) {
            mantissa = static_cast<std::int32_t>(scaled);
            return true;
        }
    }
    return false;
}

void WordList::forgetHeads() {
    headCount_ = 0;
    heads_[kWideCode] = Head{static_cast<WordKind>(0xff), 0, 0xff, 0xff};  // no word's head
    std::memset(codeCache_, kWideCode, sizeof codeCache_);
    std::fill(std::begin(plainCodes_), std::end(plainCodes_), kWideCode);
}

__attribute__((noinline, cold)) WordList::Packed WordList::plainCode(WordKind kind, char letter,
                                                                     unsigned scale) {
    const unsigned code = codeFor(Head{kind, letter, 0, static_cast<std::uint8_t>(scale)});
    if (code != kWideCode) plainCodes_[codeKey(static_cast<unsigned char>(letter), scale)] = code;
    return code;
}

unsigned WordList::codeOf(const Head& head, std::size_t key) {
    unsigned code = 0;
    while (code < headCount_ && !(heads_[code] == head))
        ++code;
    if (code == headCount_) {
        if (headCount_ == kHeadCount) return kWideCode;
        heads_[headCount_++] = head;
    }
    codeCache_[key] = static_cast<std::uint8_t>(code);
    return code;
}

WordList::Packed WordList::packNumber(WordKind kind, char letter, std::uint8_t axisIndex,
                                      std::uint32_t column, std::int32_t mantissa, unsigned scale,
                                      std::size_t index) {
    const auto bits = static_cast<std::uint8_t>(axisIndex | (scale << 2));
    if (static_cast<std::uint32_t>(mantissa) + kMantissaLimit < 2 * kMantissaLimit) {
        const unsigned code =
            codeFor(Head{kind, letter, axisIndex, static_cast<std::uint8_t>(scale)});
        if (code != kWideCode) return narrowSlot(code, mantissa);
    }
    return addWide(Wide{static_cast<std::uint8_t>(kind), static_cast<std::uint8_t>(letter), bits,
                        static_cast<std::uint8_t>(column), mantissa},
                   index);
}

WordList::Packed WordList::pack(const Word& word, std::size_t index) {
    std::int32_t mantissa = 0;
    unsigned scale = 0;
    if (packable(word, mantissa, scale))
        return packNumber(word.kind, word.letter, word.axisIndex, word.column, mantissa, scale,
                          index);
    extended_.push_back(word);
    const std::size_t at = extended_.size() - 1;
    if (at < kOverflowIndex) return kExtendedCode | (static_cast<Packed>(at) << kWideShift);
    return addWide(
        Wide{static_cast<std::uint8_t>(word.kind), static_cast<std::uint8_t>(word.letter),
             kExtendedBit, 0, static_cast<std::int32_t>(at)},
        index);
}

WordList::Packed WordList::addWide(const Wide& wide, std::size_t index) {
    if (wide_.size() < kOverflowIndex) {
        wide_.push_back(wide);
        return kWideCode | (static_cast<Packed>(wide_.size() - 1) << kWideShift);
    }
    auto it = findOverflow(overflow_, index);
    if (it != overflow_.end() && it->first == index)
        it->second = wide;
    else
        overflow_.insert(it, {static_cast<std::uint32_t>(index), wide});
    return kWideCode | (kOverflowIndex << kWideShift);
}

const WordList::Wide& WordList::wideAt(std::size_t index, Packed slot) const {
    const Packed at = slot >> kWideShift;
    if (at != kOverflowIndex) return wide_[at];
    return findOverflow(overflow_, index)->second;
}

WordList::Wide& WordList::wideAt(std::size_t index, Packed slot) {
    const Packed at = slot >> kWideShift;
    if (at != kOverflowIndex) return wide_[at];
    return findOverflow(overflow_, index)->second;
}

WordKind WordList::wholeKind(std::size_t index, Packed slot) const {
    if ((slot & kCodeMask) == kExtendedCode) return extended_[slot >> kWideShift].kind;
    const Wide& p = wideAt(index, slot);
    if (p.bits & kExtendedBit) return extended_[static_cast<std::size_t>(p.payload)].kind;
    return static_cast<WordKind>(p.kind);
}

void WordList::readWide(std::size_t index, Packed slot, Word& out) const {
    if ((slot & kCodeMask) == kExtendedCode) {
        out = extended_[slot >> kWideShift];
        return;
    }
    const Wide& p = wideAt(index, slot);
    if (p.bits & kExtendedBit) {
        out = extended_[static_cast<std::size_t>(p.payload)];
        return;
    }
    out = Word{};
    out.kind = static_cast<WordKind>(p.kind);
    out.letter = static_cast<char>(p.letter);
    out.axisIndex = p.bits & 3u;
    out.column = p.column;
    out.number = valueOf(p.payload, (p.bits >> 2) & 7u);
}

std::uint8_t WordList::columnByte(const Word& word) {
    return word.column <= kMaxPackedColumn ? static_cast<std::uint8_t>(word.column) : 0;
}

void WordList::push_back(const Word& word) {
    if (turnsFlow(word.kind, word.expr, word.number))
        turning_.push_back(static_cast<std::uint32_t>(slots_.size()));
    const Packed slot = pack(word, slots_.size());
    slots_.push_back(slot);
    columns_.push_back(columnByte(word));
}

void WordList::set(std::size_t index, const Word& word) {
    noteTurning(index, turnsFlow(word.kind, word.expr, word.number));
    columns_[index] = columnByte(word);
    const Packed slot = slots_[index];
    if ((slot & kCodeMask) == kExtendedCode) {  // keep the side-table slot, as below
        extended_[slot >> kWideShift] = word;
        return;
    }
    if ((slot & kCodeMask) != kWideCode) {
        slots_[index] = pack(word, index);
        return;
    }
    Wide& p = wideAt(index, slot);
    if (p.bits & kExtendedBit) {
        // Keep the side-table slot; repacking would leave it orphaned.
        extended_[static_cast<std::size_t>(p.payload)] = word;
        p.kind = static_cast<std::uint8_t>(word.kind);
        p.letter = static_cast<std::uint8_t>(word.letter);
        return;
    }
    std::int32_t mantissa = 0;
    unsigned scale = 0;
    if (packable(word, mantissa, scale)) {  // in the same wide slot
        p = Wide{static_cast<std::uint8_t>(word.kind), static_cast<std::uint8_t>(word.letter),
                 static_cast<std::uint8_t>(word.axisIndex | (scale << 2)),
                 static_cast<std::uint8_t>(word.column), mantissa};
        return;
    }
    extended_.push_back(word);
    p = Wide{static_cast<std::uint8_t>(word.kind), static_cast<std::uint8_t>(word.letter),
             kExtendedBit, 0, static_cast<std::int32_t>(extended_.size() - 1)};
}

void WordList::truncate(std::size_t count) {
    // The words dropped are the last ones appended: so are their wide forms.
    for (std::size_t index = slots_.size(); index-- > count;) {
        const Packed slot = slots_[index];
        if ((slot & kCodeMask) == kExtendedCode && (slot >> kWideShift) + 1 == extended_.size())
            extended_.pop_back();
        if ((slot & kCodeMask) != kWideCode) continue;
        const Packed at = slot >> kWideShift;
        if (at == kOverflowIndex && !overflow_.empty() && overflow_.back().first == index)
            overflow_.pop_back();
        else if (at != kOverflowIndex && at + 1 == wide_.size())
            wide_.pop_back();
    }
    slots_.endAt(slots_.data() + count);  // count <= size(): nothing to allocate
    columns_.endAt(columns_.data() + count);
    while (!turning_.empty() && turning_.back() >= count)
        turning_.pop_back();
}

// Out of line and cold: the parser's hot loop keeps only the call.
__attribute__((noinline, cold)) void WordList::noteFlowTurning(const Packed* slot) {
    turning_.push_back(static_cast<std::uint32_t>(slot - slots_.data()));
}

void WordList::noteTurning(std::size_t index, bool turns) {
    const auto at = std::lower_bound(turning_.begin(), turning_.end(), index);
    const bool listed = at != turning_.end() && *at == index;
    if (turns && !listed)
        turning_.insert(at, static_cast<std::uint32_t>(index));
    else if (!turns && listed)
        turning_.erase(at);
}

void WordList::shrink_to_fit() {
    if (slots_.capacity() > slots_.size() + slots_.size() / 16) {
        slots_.shrink_to_fit();
        columns_.shrink_to_fit();
    }
    if (wide_.capacity() > wide_.size() + wide_.size() / 16) wide_.shrink_to_fit();
    if (extended_.capacity() > extended_.size() + extended_.size() / 16) extended_.shrink_to_fit();
    turning_.shrink_to_fit();
}

void WordList::clear() {
    slots_.clear();
    columns_.clear();
    wide_.clear();
    overflow_.clear();
    extended_.clear();
    turning_.clear();
    forgetHeads();
}

std::size_t WordList::memoryBytes() const {
    return slots_.capacity() * sizeof(Packed) + columns_.capacity() +
           wide_.capacity() * sizeof(Wide) + overflow_.capacity() * sizeof(overflow_.front()) +
           extended_.capacity() * sizeof(Word) + turning_.capacity() * sizeof(std::uint32_t);
}

}  // namespace mtc::core
