#include "cnc_core/language/BlockList.h"

#include <algorithm>

namespace mtc::core {

bool BlockList::packable(const Block& block) {
    return block.label.length == 0 && block.comment.length == 0 && block.text.length == 0 &&
           block.subNumber == -1 && block.number >= -1 && block.number <= 32767 &&
           block.sourceText.length <= 65535 && block.lineCount <= 127;
}

BlockList::Packed BlockList::pack(const Block& block) const {
    Packed p{};
    p.firstWord = block.firstWord;
    p.sourceOffset = block.sourceText.offset;
    p.line = block.line;
    p.number =
        static_cast<std::int16_t>(block.number >= -1 && block.number <= 32767 ? block.number : -1);
    p.wordCount = block.wordCount;
    p.sourceLength =
        static_cast<std::uint16_t>(std::min<std::uint32_t>(block.sourceText.length, 65535));
    p.flags = block.flags;
    p.lineCount = static_cast<std::uint8_t>(std::min<std::uint16_t>(block.lineCount, 127));
    return p;
}

long BlockList::findExtended(std::size_t index) const {
    auto it = std::lower_bound(extendedIndex_.begin(), extendedIndex_.end(),
                               static_cast<std::uint32_t>(index));
    if (it == extendedIndex_.end() || *it != index) return -1;
    return static_cast<long>(it - extendedIndex_.begin());
}

bool BlockList::readExtended(std::size_t index, Block& out) const {
    const long slot = findExtended(index);
    if (slot < 0) return false;
    out = extended_[static_cast<std::size_t>(slot)];
    return true;
}

std::int32_t BlockList::numberAt(std::size_t index) const {
    const Packed& p = packed_[index];
    if (p.lineCount & kExtendedBit) return (*this)[index].number;
    return p.number;
}

void BlockList::push_back(const Block& block) {
    bool extended = !packable(block);
    Packed& p = packed_.emplace_back();
    p.firstWord = block.firstWord;
    p.sourceOffset = block.sourceText.offset;
    p.line = block.line;
    p.number =
        static_cast<std::int16_t>(block.number >= -1 && block.number <= 32767 ? block.number : -1);
    p.wordCount = block.wordCount;
    p.sourceLength =
        static_cast<std::uint16_t>(std::min<std::uint32_t>(block.sourceText.length, 65535));
    p.flags = block.flags;
    p.lineCount = static_cast<std::uint8_t>(std::min<std::uint16_t>(block.lineCount, 127));
    if (extended) {
        p.lineCount |= kExtendedBit;
        extendedIndex_.push_back(static_cast<std::uint32_t>(packed_.size() - 1));
        extended_.push_back(block);
    }
}

void BlockList::set(std::size_t index, const Block& block) {
    Packed p = pack(block);
    long slot = findExtended(index);
    if (packable(block)) {
        if (slot >= 0) {
            extendedIndex_.erase(extendedIndex_.begin() + slot);
            extended_.erase(extended_.begin() + slot);
        }
    } else {
        p.lineCount |= kExtendedBit;
        if (slot >= 0) {
            extended_[static_cast<std::size_t>(slot)] = block;
        } else {
            auto it = std::lower_bound(extendedIndex_.begin(), extendedIndex_.end(),
                                       static_cast<std::uint32_t>(index));
            auto position = it - extendedIndex_.begin();
            extendedIndex_.insert(it, static_cast<std::uint32_t>(index));
            extended_.insert(extended_.begin() + position, block);
        }
    }
    packed_[index] = p;
}

void BlockList::shrink_to_fit() {
    if (packed_.capacity() > packed_.size() + packed_.size() / 16) packed_.shrink_to_fit();
    extendedIndex_.shrink_to_fit();
    extended_.shrink_to_fit();
}

void BlockList::clear() {
    packed_.clear();
    extendedIndex_.clear();
    extended_.clear();
}

std::size_t BlockList::memoryBytes() const {
    return packed_.capacity() * sizeof(Packed) + extendedIndex_.capacity() * sizeof(std::uint32_t) +
           extended_.capacity() * sizeof(Block);
}

}  // namespace mtc::core
