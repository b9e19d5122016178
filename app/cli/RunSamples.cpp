#include "cli/RunSamples.h"

#include <utility>

#include "cnc_core/cell/Station.h"

namespace mtc::cli {

namespace {
constexpr double kNoSample = 1e9;  ///< s: "as far as the run goes"
}

RunSamples::RunSamples(std::uint32_t intervalMs, std::vector<std::string> axisNames)
    : interval_(intervalMs / 1000.0), names_(std::move(axisNames)) {}

double RunSamples::secondsToNextSample(const core::Station& station) const {
    if (!enabled() || limited_) return kNoSample;
    const double left = next_ - station.machine().seconds();
    return left > 0.0 ? left : 0.0;
}

void RunSamples::take(const core::Station& station, core::DiagnosticList& diagnostics) {
    if (!enabled() || limited_) return;
    // Exact to rounding: advance() used at most the time up to the sample.
    if (station.machine().seconds() < next_ - 1e-9) return;
    if (samples_.size() >= kMaxSamples) {
        limited_ = true;
        diagnostics.warning("RUN_SAMPLE_LIMIT", {},
                            "sampling stopped after " + std::to_string(kMaxSamples) +
                                " samples; a larger --sample-ms covers the whole run");
        return;
    }
    record(station);
    next_ = interval_ * static_cast<double>(samples_.size());
}

void RunSamples::finish(const core::Station& station) {
    if (!enabled() || limited_) return;
    if (!samples_.empty() && samples_.back().t >= station.machine().seconds()) return;
    record(station);
}

void RunSamples::record(const core::Station& station) {
    const core::SimulatedMachine& machine = station.machine();
    Sample sample;
    sample.t = machine.seconds();
    core::SourceLocation at = machine.currentLocation();
    sample.program = at.program;
    sample.block = std::move(at.block);
    for (std::size_t axis = 0; axis < names_.size(); ++axis)
        sample.position.push_back(machine.position(static_cast<int>(axis)));
    sample.feed = machine.actualFeed();
    samples_.push_back(std::move(sample));
}

void RunSamples::writeJson(JsonWriter& json) const {
    if (!enabled()) return;
    json.key("samples");
    json.beginArray();
    for (const Sample& s : samples_) {
        json.beginObject();
        json.key("t");
        json.value(s.t);
        json.key("program");
        json.value(s.program);
        json.key("block");
        json.value(s.block);
        json.key("position");
        json.beginObject();
        for (std::size_t axis = 0; axis < names_.size(); ++axis) {
            if (names_[axis].empty()) continue;
            json.key(names_[axis]);
            json.value(s.position[axis]);
        }
        json.endObject();
        json.key("feed");
        json.value(s.feed);
        json.endObject();
    }
    json.endArray();
}

}  // namespace mtc::cli

namespace mtc::cli {

void RunSamples::printText(std::FILE* stream) const {
    if (!enabled()) return;
    std::string line;
    for (const Sample& s : samples_) {
        line = "sample t=";
        JsonWriter::appendNumber(line, s.t);
        line += " P" + std::to_string(s.program) + ' ' + (s.block.empty() ? "-" : s.block);
        for (std::size_t axis = 0; axis < names_.size(); ++axis) {
            if (names_[axis].empty()) continue;
            line += ' ' + names_[axis] + '=';
            JsonWriter::appendNumber(line, s.position[axis]);
        }
        line += " F=";
        JsonWriter::appendNumber(line, s.feed);
        line += '\n';
        std::fwrite(line.data(), 1, line.size(), stream);
    }
}

}  // namespace mtc::cli
