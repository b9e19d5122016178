#include "cnc_core/afc/AfcTrendRecorder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <utility>

namespace mtc::core {
namespace {

/// `value` with `decimals` digits after a '.' whatever the C locale says.
void appendFixed(std::string& out, double value, int decimals) {
    long long scale = 1;
    for (int i = 0; i < decimals; ++i)
        scale *= 10;
    const long long scaled =
        std::llround(std::clamp(value, -1e12, 1e12) * static_cast<double>(scale));
    const unsigned long long magnitude =
        static_cast<unsigned long long>(scaled < 0 ? -scaled : scaled);
    char text[48];
    std::snprintf(text, sizeof text, "%s%llu.%0*llu", scaled < 0 ? "-" : "", magnitude / scale,
                  decimals, magnitude % scale);
    out += text;
}

}  // namespace

AfcTrendRecorder::AfcTrendRecorder(std::size_t capacity)
    : capacity_(std::max<std::size_t>(capacity, 2)) {}

void AfcTrendRecorder::add(const AfcTrendSample& sample) {
    Entry& entry = entries_.emplace_back();
    entry.move.constant = sample;
    entry.move.count = 1;
    keep(entry);
}

void AfcTrendRecorder::add(const AfcObservedMove& move) {
    addObserved([&move](AfcObservedMove& kept) { kept = move; });
}

void AfcTrendRecorder::keep(Entry& entry) {
    ++revision_;
    entry.first = added_;
    const auto samples = static_cast<std::size_t>(entry.move.count);
    added_ += samples;
    count_ += samples;
    // Drop the oldest samples beyond the capacity: whole entries, then the
    // first samples of the oldest one left. The new entry itself is never
    // dropped whole: the excess is always less than its samples.
    while (count_ > capacity_) {
        const auto left = static_cast<std::size_t>(entries_.front().move.count - skipped_);
        const std::size_t excess = count_ - capacity_;
        if (excess < left) {
            skipped_ += static_cast<int>(excess);
            count_ -= excess;
            break;
        }
        entries_.pop_front();
        skipped_ = 0;
        count_ -= left;
    }
}

AfcTrendSample AfcTrendRecorder::at(std::size_t index) const {
    if (entries_.empty()) return {};
    const std::uint64_t wanted =
        entries_.front().first + static_cast<std::uint64_t>(skipped_) + std::min(index, count_ - 1);
    // The last entry that starts at or before the wanted sample (the front
    // does: it holds the oldest kept sample).
    const auto after = std::upper_bound(
        entries_.begin() + 1, entries_.end(), wanted,
        [](std::uint64_t sample, const Entry& entry) { return sample < entry.first; });
    const Entry& entry = *std::prev(after);
    return entry.sample(static_cast<int>(wanted - entry.first) + 1);
}

template <typename Visit>
void AfcTrendRecorder::forEach(Visit visit) const {
    int from = skipped_ + 1;
    for (const Entry& entry : entries_) {
        for (int k = from; k <= entry.move.count; ++k)
            visit(entry.sample(k));
        from = 1;
    }
}

std::vector<AfcTrendSample> AfcTrendRecorder::samples() const {
    std::vector<AfcTrendSample> list;
    list.reserve(count_);
    forEach([&list](const AfcTrendSample& s) { list.push_back(s); });
    return list;
}

void AfcTrendRecorder::clear() {
    entries_.clear();
    skipped_ = 0;
    count_ = 0;
    added_ = 0;
    ++revision_;
}

std::string AfcTrendRecorder::csv() const {
    std::string text =
        "time_s,torque_actual_pct,machining_torque_pct,idle_torque_pct,limiting_torque_pct,"
        "minimum_torque_pct,maximum_idle_torque_pct,feed_reduction_pct,peak_reduction_pct,"
        "maximum_reduction_pct,effective_feed_mm_min,g26,stall_torque_pct,itm,excth,thmis\n";
    forEach([&text](const AfcTrendSample& s) {
        appendFixed(text, s.time, 4);
        for (double value : {s.torqueActual, s.machiningTorque, s.idleTorque, s.limitingTorque,
                             s.minimumTorque, s.maximumIdleTorque, s.feedReduction, s.peakReduction,
                             s.maximumReduction, s.effectiveFeed}) {
            text += ',';
            appendFixed(text, value, 3);
        }
        text += s.active ? ",1," : ",0,";
        appendFixed(text, s.stallTorque, 3);
        for (bool flag : {s.measuringIdle, s.excessiveThrust, s.thrustMissing})
            text += flag ? ",1" : ",0";
        text += '\n';
    });
    return text;
}

}  // namespace mtc::core
