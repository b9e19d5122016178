#pragma once

#include <array>
#include <bitset>

namespace mtc::core {

/// The events of the cell ("process:event", e.g. 1:15) that BES, BER, BEV and
/// JEV test. The SPS and the GUI set them; one table per cell, shared by the
/// interpreters of all processes.
class EventTable {
  public:
    static constexpr int kProcesses = 7;
    static constexpr int kEvents = 256;

    /// True when `process:event` is a valid address (process 0..6, event 0..255).
    static bool valid(int process, int event) {
        return process >= 0 && process < kProcesses && event >= 0 && event < kEvents;
    }
    /// Sets or resets an event; returns false (and changes nothing) for an invalid address.
    bool set(int process, int event, bool value) {
        if (!valid(process, event)) return false;
        bits_[static_cast<size_t>(process)][static_cast<size_t>(event)] = value;
        return true;
    }
    /// The event's state; false for an invalid address.
    bool get(int process, int event) const {
        return valid(process, event) &&
               bits_[static_cast<size_t>(process)][static_cast<size_t>(event)];
    }
    /// Resets every event.
    void clear() { bits_ = {}; }

  private:
    std::array<std::bitset<kEvents>, kProcesses> bits_{};
};

}  // namespace mtc::core
