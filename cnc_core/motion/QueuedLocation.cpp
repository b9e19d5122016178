#include "cnc_core/motion/QueuedLocation.h"

namespace mtc::core::motion {

void QueuedLocation::assignLong(const std::string& text) {
    long_ = std::make_shared<const std::string>(text);
    size_ = kLong;
}

SourceLocation QueuedLocation::location() const {
    SourceLocation where;
    where.program = program_;
    if (size_ == kLong)
        where.block = *long_;
    else
        where.block.assign(text_.data(), size_);
    where.line = line_;
    where.column = column_;
    return where;
}

}  // namespace mtc::core::motion
