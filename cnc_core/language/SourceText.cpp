#include "cnc_core/language/SourceText.h"

namespace mtc::core {

/// Counts in chunks of 255 bytes with 8-bit counters, which the compiler
/// turns into byte-wise vector compares.
void countLinesAndBlanks(std::string_view text, std::size_t& lines, std::size_t& blanks) {
    const char* p = text.data();
    std::size_t left = text.size();
    while (left > 0) {
        std::size_t chunk = left < 255 ? left : 255;
        std::uint8_t newlines = 0, spaces = 0;
        for (std::size_t i = 0; i < chunk; ++i) {
            newlines = static_cast<std::uint8_t>(newlines + (p[i] == '\n'));
            spaces = static_cast<std::uint8_t>(spaces + (p[i] == ' '));
        }
        lines += newlines;
        blanks += spaces;
        p += chunk;
        left -= chunk;
    }
}

}  // namespace mtc::core
