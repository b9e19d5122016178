#pragma once

// Wall time and peak memory of the benchmark tools that time whole screens
// or processes (toolpath view, editor): one copy for all of them.
#include <sys/resource.h>

#include <chrono>

namespace mtc::bench {

using Clock = std::chrono::steady_clock;

/// Milliseconds since `start`.
inline double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// Peak resident memory of this process in MiB (getrusage, ru_maxrss).
inline double peakRssMb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace mtc::bench
