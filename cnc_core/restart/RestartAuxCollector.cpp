#include "cnc_core/restart/RestartAuxCollector.h"

namespace mtc::core {

RestartAuxCollector::RestartAuxCollector(const ProcessConfig& config) {
    const AuxFunctionGroups groups(config);
    for (int m = 0; m < AuxFunctionGroups::kFunctions; ++m)
        storedInM16_[static_cast<std::size_t>(m)] = groups.storedInBuffer(m);
}

void RestartAuxCollector::clear() {
    m16_.clear();
    q_.clear();
    seen_ = 0;
    forwarded_ = 0;
}

void RestartAuxCollector::auxiliary(const AuxOutput& output, bool forwarded) {
    ++seen_;
    forwarded_ += forwarded ? 1 : 0;
    if (output.type == 'Q') {
        q_.push(static_cast<int>(output.value));
    } else if (output.type == 'M') {
        const int m = static_cast<int>(output.value);
        if (storesInM16(m)) m16_.push(m);
    }
}

}  // namespace mtc::core
