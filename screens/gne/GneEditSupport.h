#pragma once

// Helpers shared by the two halves of GneEditModel (GneEditModel.cpp: the
// section and its editing; GneEditOutput.cpp: what goes back into the
// program). Internal to screens/gne.

#include <cstdint>
#include <string>
#include <vector>

#include "cnc_core/contour/GneModel.h"

namespace mtc::screens::gneedit {

/// Section items carry these lines while solved and expanded, so that a
/// diagnostic names its item and element: base + 1000 * item + element + 1.
inline constexpr std::uint32_t kLineBase = 100000;
inline constexpr std::uint32_t kItemStride = 1000;

inline std::string trimmed(const std::string& s) {
    std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

inline std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find('\n', start);
        lines.push_back(text.substr(start, end == std::string::npos ? end : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return lines;
}

inline bool isWindow(const mtc::core::gne::GneItem& item) {
    return !item.isContour && item.call.keyword.rfind("WINDOW_", 0) == 0;
}
inline bool isCycle(const mtc::core::gne::GneItem& item) {
    return !item.isContour && item.call.keyword.rfind("CYCLE_", 0) == 0;
}

}  // namespace mtc::screens::gneedit
