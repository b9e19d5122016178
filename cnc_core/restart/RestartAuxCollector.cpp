#include "cnc_core/restart/RestartAuxCollector.h"

namespace mtc::core {

namespace {

bool isProgramControl(int m) {
    return m == 0 || m == 1 || m == 2 || m == 30;
}

/// M19 of the main spindle and of spindles 1..3 (seed 000, 4.2: never stored).
bool isSpindleOrientation(int m) {
    return m % 100 == 19 && m / 100 <= 3;
}

}  // namespace

RestartAuxCollector::RestartAuxCollector(const ProcessConfig& config) {
    m16Member_.fill(true);
    for (const auto& group : config.mGroups)
        if (group.number >= 1 && group.number <= 15)
            for (int m : group.functions)
                if (m >= 0 && m < 1000) m16Member_[static_cast<std::size_t>(m)] = false;
    for (int m = 0; m < 1000; ++m)
        if (isProgramControl(m) || isSpindleOrientation(m))
            m16Member_[static_cast<std::size_t>(m)] = false;
}

bool RestartAuxCollector::storesInM16(int m) const {
    return m >= 0 && m < 1000 && m16Member_[static_cast<std::size_t>(m)];
}

void RestartAuxCollector::clear() {
    m16_.clear();
    q_.clear();
    seen_ = 0;
    forwarded_ = 0;
}

void RestartAuxCollector::auxiliary(const AuxOutput& output, bool forwarded) {
    ++seen_;
    if (forwarded) ++forwarded_;
    const int value = static_cast<int>(output.value);
    if (output.type == 'M' && storesInM16(value)) m16_.push(value);
    if (output.type == 'Q') q_.push(value);
}

}  // namespace mtc::core
