#include "cnc_core/machine/OverrideSwitch.h"

#include <algorithm>
#include <vector>

namespace mtc::core {

namespace {

/// The position after `percent` in `direction` among the sorted `positions`.
int step(const std::vector<int>& positions, int percent, int direction) {
    if (direction > 0) {
        for (int p : positions)
            if (p > percent) return p;
        return positions.back();
    }
    if (direction < 0) {
        for (auto it = positions.rbegin(); it != positions.rend(); ++it)
            if (*it < percent) return *it;
        return positions.front();
    }
    return std::clamp(percent, positions.front(), positions.back());
}

}  // namespace

int feedOverrideStep(int percent, int direction, int maxPercent) {
    const int top = std::clamp(maxPercent, 10, 200);
    std::vector<int> positions = {0, 1, 2, 4, 6, 8, 10};
    for (int p = 20; p < top; p += 10)
        positions.push_back(p);
    if (positions.back() != top) positions.push_back(top);
    return step(positions, percent, direction);
}

int rapidOverrideStep(int percent, int direction) {
    static const std::vector<int> positions = {0, 1, 10, 25, 50, 100};
    return step(positions, percent, direction);
}

}  // namespace mtc::core
