#include "cnc_core/language/WordList.h"

#include <cmath>

namespace mtc::core {

bool WordList::packable(const Word& word, std::int32_t& mantissa, unsigned& scale) {
    if (word.kind >= WordKind::Assign || word.expr >= 0 || word.target >= 0 ||
        word.text.length != 0 || word.args.length != 0 || word.eventProcess != -1 ||
        word.eventNumber != -1 || word.flags != 0 || word.axisIndex > 3 || word.column == 0 ||
        word.column > 255 || !std::isfinite(word.number))
        return false;
    for (scale = 0; scale < 8; ++scale) {
        double scaled = std::nearbyint(word.number * kPow10[scale]);
        if (std::fabs(scaled) > 2147483647.0) return false;
        if (scaled / kPow10[scale] == word.number &&
            !(scaled == 0.0 && std::signbit(word.number))) {
            mantissa = static_cast<std::int32_t>(scaled);
            return true;
        }
    }
    return false;
}

WordList::Packed WordList::pack(const Word& word) {
    std::int32_t mantissa = 0;
    unsigned scale = 0;
    if (packable(word, mantissa, scale)) {
        return Packed{static_cast<std::uint8_t>(word.kind), static_cast<std::uint8_t>(word.letter),
                      static_cast<std::uint8_t>(word.axisIndex | (scale << 2)),
                      static_cast<std::uint8_t>(word.column), mantissa};
    }
    extended_.push_back(word);
    return Packed{static_cast<std::uint8_t>(word.kind), static_cast<std::uint8_t>(word.letter),
                  kExtendedBit, 0, static_cast<std::int32_t>(extended_.size() - 1)};
}

void WordList::push_back(const Word& word) {
    packed_.push_back(pack(word));
}

void WordList::set(std::size_t index, const Word& word) {
    Packed& p = packed_[index];
    if (p.bits & kExtendedBit) {
        // Keep the side-table slot; repacking would leave it orphaned.
        extended_[static_cast<std::size_t>(p.payload)] = word;
        p.kind = static_cast<std::uint8_t>(word.kind);
        p.letter = static_cast<std::uint8_t>(word.letter);
        return;
    }
    p = pack(word);
}

void WordList::shrink_to_fit() {
    if (packed_.capacity() > packed_.size() + packed_.size() / 16) packed_.shrink_to_fit();
    if (extended_.capacity() > extended_.size() + extended_.size() / 16) extended_.shrink_to_fit();
}

void WordList::clear() {
    packed_.clear();
    extended_.clear();
}

std::size_t WordList::memoryBytes() const {
    return packed_.capacity() * sizeof(Packed) + extended_.capacity() * sizeof(Word);
}

}  // namespace mtc::core
