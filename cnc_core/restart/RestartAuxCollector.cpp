#include "cnc_core/restart/RestartAuxCollector.h"

namespace mtc::core {

RestartAuxCollector::RestartAuxCollector(const ProcessConfig& config) : groups_(config) {}

bool RestartAuxCollector::storesInM16(int m) const {
    return groups_.storedInBuffer(m);
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
