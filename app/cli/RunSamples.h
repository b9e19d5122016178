#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/JsonWriter.h"
#include "cnc_core/language/Diagnostic.h"

namespace mtc::core {
class Station;
}

namespace mtc::cli {

/// The samples of `run --sample-ms N` (CLI-CONTRACT.md "Extensions"): what
/// the machine did every N ms of simulated time from Start: time, program,
/// block, machine position per axis, actual path feed.
class RunSamples {
  public:
    /// At most this many samples; past it sampling stops with a warning.
    static constexpr std::size_t kMaxSamples = 100'000;

    /// Sampling every `intervalMs` (0 = off) with the axis names of the
    /// report ("" = an axis not reported).
    RunSamples(std::uint32_t intervalMs, std::vector<std::string> axisNames);

    bool enabled() const { return interval_ > 0.0; }
    /// Simulated time the station may go on before the next sample is
    /// due (a huge value when sampling is off).
    double secondsToNextSample(const core::Station& station) const;
    /// Takes a sample when one is due (and the very first one at Start).
    void take(const core::Station& station, core::DiagnosticList& diagnostics);
    /// The last sample at the end of the run, when time passed since the last one.
    void finish(const core::Station& station);
    /// Writes "samples": [...] as the next key of the open object.
    void writeJson(JsonWriter& json) const;
    /// One line per sample: "sample t=1.250 P1 N0002 X=10 Y=0 F=600".
    void printText(std::FILE* stream) const;

  private:
    struct Sample {
        double t = 0.0;
        int program = 0;
        std::string block;
        std::vector<double> position;
        double feed = 0.0;
    };
    void record(const core::Station& station);

    double interval_;
    double next_ = 0.0;
    bool limited_ = false;
    std::vector<std::string> names_;
    std::vector<Sample> samples_;
};

}  // namespace mtc::cli
