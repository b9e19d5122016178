#include "cnc_core/language/BlockList.h"

#include <algorithm>

namespace mtc::core {

bool BlockList::pack(const Block& block, std::size_t index, Packed& p) const {
    // What is always kept whole first (a compiled program's sub-numbered
    // blocks), before the anchor is read.
    if (block.subNumber != -1 || block.label.length != 0 || block.comment.length != 0 ||
        block.text.length != 0)
        return false;
    const Anchor& a = anchors_[index / kGroup];
    const std::uint32_t wordDelta = block.firstWord - a.firstWord;
    const std::uint32_t sourceDelta = block.sourceText.offset - a.sourceOffset;
    const std::uint32_t lineDelta = block.line - a.line;
    if (block.number < -1 || block.number > 32767 || block.sourceText.length > 255 ||
        block.wordCount > 255 || block.lineCount > 127 ||
        (wordDelta | sourceDelta | lineDelta) > 0xffff)
        return false;
    p.wordDelta = static_cast<std::uint16_t>(wordDelta);
    p.sourceDelta = static_cast<std::uint16_t>(sourceDelta);
    p.lineDelta = static_cast<std::uint16_t>(lineDelta);
    p.number = static_cast<std::int16_t>(block.number);
    p.wordCount = static_cast<std::uint8_t>(block.wordCount);
    p.sourceLength = static_cast<std::uint8_t>(block.sourceText.length);
    p.flags = block.flags;
    p.lineCount = static_cast<std::uint8_t>(block.lineCount);
    return true;
}

void BlockList::anchorFor(const Block& block) {
    if (packed_.size() % kGroup != 0) return;
    group_ = Anchor{block.firstWord, block.sourceText.offset, block.line};
    groupFirst_ = static_cast<std::uint32_t>(packed_.size());
    anchors_.push_back(group_);
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
    anchorFor(block);
    append(block);
}

void BlockList::append(const Block& block) {
    const std::size_t index = packed_.size();
    Packed p{};
    if (!pack(block, index, p)) {
        // The number stays readable by numberAt's fast path too.
        p.number = static_cast<std::int16_t>(
            block.number >= -1 && block.number <= 32767 ? block.number : -1);
        p.lineCount = kExtendedBit;
        extendedIndex_.push_back(static_cast<std::uint32_t>(index));
        extended_.push_back(block);
    }
    packed_.push_back(p);
}

void BlockList::pushPlainWhole(std::uint32_t firstWord, std::uint16_t wordCount,
                               std::int16_t number, std::uint32_t line, std::uint32_t sourceOffset,
                               std::uint32_t sourceLength) {
    Block block;
    block.firstWord = firstWord;
    block.wordCount = wordCount;
    block.number = number;
    block.line = line;
    block.sourceText = TextSpan{sourceOffset, sourceLength};
    push_back(block);
}

void BlockList::set(std::size_t index, const Block& block) {
    Packed p{};
    const bool packed = pack(block, index, p);
    const long slot = findExtended(index);
    if (packed) {
        if (slot >= 0) {
            extendedIndex_.erase(extendedIndex_.begin() + slot);
            extended_.erase(extended_.begin() + slot);
        }
    } else {
        p.number = static_cast<std::int16_t>(
            block.number >= -1 && block.number <= 32767 ? block.number : -1);
        p.lineCount = kExtendedBit;
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
    anchors_.shrink_to_fit();
    extendedIndex_.shrink_to_fit();
    extended_.shrink_to_fit();
}

void BlockList::clear() {
    packed_.clear();
    anchors_.clear();
    group_ = Anchor{};
    groupFirst_ = 0 - kGroup;
    extendedIndex_.clear();
    extended_.clear();
}

std::size_t BlockList::memoryBytes() const {
    return packed_.capacity() * sizeof(Packed) + anchors_.capacity() * sizeof(Anchor) +
           extendedIndex_.capacity() * sizeof(std::uint32_t) + extended_.capacity() * sizeof(Block);
}

}  // namespace mtc::core
