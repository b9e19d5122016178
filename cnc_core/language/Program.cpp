#include "cnc_core/language/Program.h"

#include <algorithm>
#include <cstdio>

namespace mtc::core {

std::string Program::blockId(std::size_t blockIndex) const {
    if (blockIndex >= blocks.size()) return {};
    const Block block = blocks[blockIndex];
    if (block.number < 0) return {};
    char buffer[24];
    if (block.subNumber >= 0)
        std::snprintf(buffer, sizeof buffer, "N%04d:%04d", block.number, block.subNumber);
    else
        std::snprintf(buffer, sizeof buffer, "N%04d", block.number);
    return buffer;
}

long Program::findLabel(std::string_view name) const {
    auto it = labels.find(std::string(name));
    return it == labels.end() ? -1 : static_cast<long>(it->second);
}

std::uint32_t Program::lineOf(std::uint32_t offset) const {
    const std::string_view before = source.span(0, offset);
    return 1 + static_cast<std::uint32_t>(std::count(before.begin(), before.end(), '\n'));
}

std::size_t Program::memoryBytes() const {
    std::size_t bytes = sizeof(Program) + source.memoryBytes() + name.capacity() +
                        identification.capacity() + header.capacity() + title.capacity() +
                        cycleCall.capacity();
    bytes += blocks.memoryBytes() + words.memoryBytes();
    bytes += expressions.capacity() * sizeof(ExprNode);
    // unordered_map: bucket array + one node (key string + value + link) per label.
    bytes += labels.bucket_count() * sizeof(void*);
    for (const auto& entry : labels)
        bytes += sizeof(void*) * 2 + sizeof(entry) + entry.first.capacity();
    bytes += cycleParameters.capacity() * sizeof(CycleParameter);
    for (const auto& d : diagnostics.items())
        bytes += sizeof(Diagnostic) + d.code.capacity() + d.message.capacity() +
                 d.where.block.capacity();
    return bytes;
}

}  // namespace mtc::core
