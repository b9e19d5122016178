#include "cnc_core/language/Program.h"

#include <cstdio>

namespace mtc::core {

std::string Program::blockId(std::size_t blockIndex) const {
    if (blockIndex >= blocks.size() || blocks[blockIndex].number < 0) return {};
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "N%04d", blocks[blockIndex].number);
    return buffer;
}

long Program::findLabel(std::string_view name) const {
    auto it = labels.find(std::string(name));
    return it == labels.end() ? -1 : static_cast<long>(it->second);
}

}  // namespace mtc::core
