#include "cnc_core/afc/AfcTrendRecorder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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
    : buffer_(std::max<std::size_t>(capacity, 2)) {}

void AfcTrendRecorder::add(const AfcTrendSample& sample) {
    ++revision_;
    if (count_ < buffer_.size()) {
        buffer_[(first_ + count_++) % buffer_.size()] = sample;
        return;
    }
    buffer_[first_] = sample;
    first_ = (first_ + 1) % buffer_.size();
}

const AfcTrendSample& AfcTrendRecorder::at(std::size_t index) const {
    return buffer_[(first_ + std::min(index, count_ - 1)) % buffer_.size()];
}

std::vector<AfcTrendSample> AfcTrendRecorder::samples() const {
    std::vector<AfcTrendSample> list;
    list.reserve(count_);
    for (std::size_t i = 0; i < count_; ++i)
        list.push_back(at(i));
    return list;
}

void AfcTrendRecorder::clear() {
    first_ = count_ = 0;
    ++revision_;
}

std::string AfcTrendRecorder::csv() const {
    std::string text =
        "time_s,torque_actual_pct,machining_torque_pct,idle_torque_pct,limiting_torque_pct,"
        "minimum_torque_pct,maximum_idle_torque_pct,feed_reduction_pct,peak_reduction_pct,"
        "maximum_reduction_pct,effective_feed_mm_min,g26,stall_torque_pct,itm,excth,thmis\n";
    for (std::size_t i = 0; i < count_; ++i) {
        const AfcTrendSample& s = at(i);
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
    }
    return text;
}

}  // namespace mtc::core
