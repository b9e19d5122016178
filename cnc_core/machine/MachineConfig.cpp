#include "cnc_core/machine/MachineConfig.h"

#include <algorithm>
#include <cstdlib>

#include "cnc_core/machine/ConfigText.h"

namespace mtc::core {

const AxisConfig* ProcessConfig::axis(const std::string& axisName) const {
    for (const auto& a : axes)
        if (a.name == axisName) return &a;
    return nullptr;
}

const ToolConfig* ProcessConfig::tool(int toolNumber) const {
    for (const auto& t : tools)
        if (t.number == toolNumber) return &t;
    return nullptr;
}

const MGroupConfig* ProcessConfig::mGroupOf(int mFunction) const {
    for (const auto& g : mGroups)
        if (std::find(g.functions.begin(), g.functions.end(), mFunction) != g.functions.end())
            return &g;
    return nullptr;
}

bool parseYesNo(const std::string& text, bool& value) {
    std::string v = text;
    std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return std::tolower(c); });
    if (v == "yes" || v == "1" || v == "true") {
        value = true;
        return true;
    }
    if (v == "no" || v == "0" || v == "false") {
        value = false;
        return true;
    }
    return false;
}

bool ProcessConfig::flag(const std::string& key, bool fallback) const {
    auto it = parameters.find(key);
    bool value = fallback;
    if (it != parameters.end()) parseYesNo(it->second, value);
    return value;
}

double ProcessConfig::number(const std::string& key, double fallback) const {
    auto it = parameters.find(key);
    if (it == parameters.end()) return fallback;
    double value = 0.0;  // locale independent: the panel runs under the desktop's locale
    return readDecimal(it->second, value) == NumberProblem::None ? value : fallback;
}

const ProcessConfig* MachineConfig::process(int index) const {
    for (const auto& p : processes)
        if (p.index == index) return &p;
    return nullptr;
}

}  // namespace mtc::core
