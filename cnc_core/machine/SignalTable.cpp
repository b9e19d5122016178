#include "cnc_core/machine/SignalTable.h"

namespace mtc::core {

bool SignalTable::set(const std::string& name, int value) {
    auto [it, inserted] = values_.try_emplace(name, 0);
    if (!inserted && it->second == value) return false;
    if (inserted && value == 0) return false;
    it->second = value;
    log_.push_back({name, value, ++step_});
    return true;
}

int SignalTable::get(const std::string& name) const {
    auto it = values_.find(name);
    return it == values_.end() ? 0 : it->second;
}

}  // namespace mtc::core
