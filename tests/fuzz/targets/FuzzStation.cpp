#include "FuzzStation.h"

#include <cmath>

#include "../FuzzTargets.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace mtc::fuzz {

void FiniteSink::motion(const core::Motion& m) {
    bool finite = std::isfinite(m.feed) && std::isfinite(m.center1) && std::isfinite(m.center2) &&
                  std::isfinite(m.effectiveRadius) && m.axisCount >= 0 &&
                  m.axisCount <= core::kMaxAxes;
    for (int a = 0; finite && a < m.axisCount; ++a)
        finite = std::isfinite(m.start[static_cast<std::size_t>(a)]) &&
                 std::isfinite(m.end[static_cast<std::size_t>(a)]);
    require(finite, "motions carry finite positions, centres and feeds", input_);
}

void FiniteSink::auxiliary(const core::AuxOutput& a) {
    require(std::isfinite(a.value), "aux functions carry finite values", input_);
}

void FiniteSink::dwell(const core::SourceLocation&, double seconds) {
    require(std::isfinite(seconds) && seconds >= 0.0, "dwell times are finite", input_);
}

FuzzStation::FuzzStation(const core::ProcessConfig& process, std::string_view input) : sink(input) {
    interpreter = std::make_unique<core::Interpreter>(process, store, sink);
    auto* data = dynamic_cast<core::MachineDataStore*>(&interpreter->machineData());
    if (data) afc = std::make_shared<core::AdaptiveFeedControl>(process, *data);
    interpreter->setAdaptiveFeed(afc);
}

}  // namespace mtc::fuzz
