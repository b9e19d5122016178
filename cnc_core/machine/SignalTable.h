#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace mtc::core {

/// One change of an interface signal, in the order it happened.
struct SignalChange {
    std::string name;
    int value = 0;
    std::uint64_t step = 0;  ///< running number of the change (1, 2, ...)
};

/// The NC <-> SPS interface signals of one process (e.g. P00SBPACT, P00CADV)
/// and the log of their changes. Setting a signal to the value it already
/// has is not a change and is not logged.
class SignalTable {
  public:
    /// Sets `name` to `value`; logs the change. Returns true if it changed.
    bool set(const std::string& name, int value);
    /// Current value; 0 for a signal never set.
    int get(const std::string& name) const;
    const std::map<std::string, int>& values() const { return values_; }
    const std::vector<SignalChange>& log() const { return log_; }
    /// Counts every change since the table was made (never goes back, not
    /// even with clearLog()): a reader may keep a value while it stands.
    std::uint64_t changes() const { return step_; }
    /// Forgets the log (values stay).
    void clearLog() { log_.clear(); }

  private:
    std::map<std::string, int> values_;
    std::vector<SignalChange> log_;
    std::uint64_t step_ = 0;
};

}  // namespace mtc::core
