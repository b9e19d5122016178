#include "cnc_core/machine/MachineConfigReader.h"

#include <cstdlib>
#include <functional>
#include <sstream>

#include "cnc_core/afc/AfcParameterRanges.h"
#include "cnc_core/toolpath/Stock.h"

namespace mtc::core {
namespace {

std::string trim(std::string_view s) {
    size_t b = 0, e = s.size();
    while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r'))
        ++b;
    while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r'))
        --e;
    return std::string(s.substr(b, e - b));
}

std::vector<std::string> splitWords(const std::string& s, char separator = ' ') {
    std::vector<std::string> words;
    std::string current;
    for (char c : s) {
        if (c == separator || (separator == ' ' && c == '\t')) {
            if (!trim(current).empty()) words.push_back(trim(current));
            current.clear();
        } else {
            current += c;
        }
    }
    if (!trim(current).empty()) words.push_back(trim(current));
    return words;
}

bool parseDouble(const std::string& s, double& out) {
    if (s.empty()) return false;
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return end != s.c_str() && *end == '\0';
}

bool parseInt(const std::string& s, int& out) {
    double d = 0;
    if (!parseDouble(s, d) || d != static_cast<int>(d)) return false;
    out = static_cast<int>(d);
    return true;
}

/// Reads one configuration text section by section.
class Reader {
  public:
    explicit Reader(MachineConfigReadResult& result) : r_(result) {}

    void run(std::string_view text) {
        int lineNo = 0;
        size_t pos = 0;
        while (pos <= text.size()) {
            size_t nl = text.find('\n', pos);
            if (nl == std::string_view::npos) nl = text.size();
            ++lineNo;
            line_ = lineNo;
            handleLine(text.substr(pos, nl - pos));
            pos = nl + 1;
        }
        if (r_.config.processes.empty())
            error("CFG_NO_PROCESS", "the configuration defines no process");
    }

  private:
    void error(const std::string& code, const std::string& message) {
        r_.diagnostics.error(code, {0, "", line_, 0}, message);
    }

    void handleLine(std::string_view raw) {
        std::string text = trim(raw.substr(0, raw.find('#')));
        if (text.empty()) return;
        if (text.front() == '[') {
            if (text.back() != ']') return error("CFG_SYNTAX", "section header without ']'");
            openSection(splitWords(text.substr(1, text.size() - 2)));
            return;
        }
        size_t eq = text.find('=');
        if (eq == std::string::npos) return error("CFG_SYNTAX", "expected 'key = value'");
        std::string key = trim(std::string_view(text).substr(0, eq));
        std::string value = trim(std::string_view(text).substr(eq + 1));
        if (!handler_) return error("CFG_SYNTAX", "key '" + key + "' outside any section");
        handler_(key, value);
    }

    ProcessConfig* processFor(const std::string& index) {
        int n = 0;
        if (!parseInt(index, n) || n < 0 || n > 6) {
            error("CFG_PROCESS", "process number must be 0..6, got '" + index + "'");
            return nullptr;
        }
        for (auto& p : r_.config.processes)
            if (p.index == n) return &p;
        error("CFG_PROCESS",
              "process " + index + " used before its [process " + index + "] section");
        return nullptr;
    }

    void openSection(const std::vector<std::string>& words) {
        handler_ = nullptr;
        if (words.size() == 1 && words[0] == "cell") {
            handler_ = [this](const std::string& k, const std::string& v) { cellKey(k, v); };
            return;
        }
        if (words.size() >= 2 && words[0] == "process") {
            if (words.size() == 2) return openProcess(words[1]);
            ProcessConfig* p = processFor(words[1]);
            if (!p) return;
            if (words.size() == 4 && (words[2] == "axis" || words[2] == "spindle"))
                return openAxis(*p, words[3], words[2] == "spindle");
            if (words.size() == 4 && words[2] == "mgroup") return openMGroup(*p, words[3]);
            if (words.size() == 3 && words[2] == "tools") return openTools(*p);
            if (words.size() == 3 && words[2] == "zero-offsets") return openZeroOffsets(*p);
            if (words.size() == 3 && words[2] == "torque-model") return openTorqueModel(*p);
            if (words.size() == 4 && words[2] == "page") return openPage(*p, words[3]);
        }
        error("CFG_SECTION", "unknown section");
    }

    void cellKey(const std::string& key, const std::string& value) {
        if (key == "name")
            r_.config.name = value;
        else if (key == "md_password" && !value.empty() && value.find(' ') == std::string::npos)
            r_.config.machineDataPassword = value;
        else if (key == "md_password")
            error("CFG_VALUE", "md_password must be one word");
        else
            error("CFG_KEY", "unknown key '" + key + "' in [cell]");
    }

    void openProcess(const std::string& index) {
        int n = 0;
        if (!parseInt(index, n) || n < 0 || n > 6)
            return error("CFG_PROCESS", "process number must be 0..6, got '" + index + "'");
        for (const auto& p : r_.config.processes)
            if (p.index == n) return error("CFG_PROCESS", "process " + index + " defined twice");
        r_.config.processes.push_back({});
        r_.config.processes.back().index = n;
        const size_t slot = r_.config.processes.size() - 1;
        handler_ = [this, slot](const std::string& k, const std::string& v) {
            ProcessConfig& p = r_.config.processes[slot];
            if (k == "name")
                p.name = v;
            else if (k == "tool_places" && parseInt(v, p.toolPlaces)) {
            } else if (k == "tool_storage" && (v == "magazine" || v == "turret"))
                p.toolStorage = v;
            else if (k == "stock")
                readStock(p, v);
            else if (k.size() == 4 && k[0] == 'B')
                processParameter(p, k, v);
            else
                error("CFG_KEY", "unknown key or bad value '" + k + " = " + v + "' in [process]");
        };
    }

    /// `Bxxx = value`: kept as text; the values whose range the simulator
    /// knows (adaptive feed control B062..B069, seed 002 4.2) are checked here
    /// so that a bad one names its line, key, value and range.
    void processParameter(ProcessConfig& p, const std::string& key, const std::string& value) {
        double parsed = 0.0;
        if (isAfcParameter(key) && !readAfcParameterValue(key, value, parsed))
            return error("CFG_VALUE", "process " + std::to_string(p.index) + " parameter " + key +
                                          " = '" + value +
                                          "' is not allowed: " + afcAllowedValues(key));
        p.parameters[key] = value;
    }

    /// `stock = block ...` / `cylinder ...` / `none` (cnc_core/toolpath/Stock.h).
    void readStock(ProcessConfig& p, const std::string& value) {
        Stock stock;
        std::string problem;
        if (!parseStock(value, stock, problem)) return error("CFG_STOCK", problem);
        p.stock = value;
    }

    void openAxis(ProcessConfig& p, const std::string& name, bool spindle) {
        if (p.axis(name)) return error("CFG_AXIS", "axis " + name + " defined twice");
        p.axes.push_back({});
        p.axes.back().name = name;
        p.axes.back().kind = spindle ? AxisKind::Spindle : AxisKind::Linear;
        if (spindle) p.axes.back().definitions = {name};
        const int process = p.index;
        const size_t slot = p.axes.size() - 1;
        handler_ = [this, process, slot](const std::string& k, const std::string& v) {
            axisKey(r_.config.processes[indexOf(process)].axes[slot], k, v);
        };
    }

    size_t indexOf(int process) const {
        for (size_t i = 0; i < r_.config.processes.size(); ++i)
            if (r_.config.processes[i].index == process) return i;
        return 0;
    }

    void axisKey(AxisConfig& a, const std::string& k, const std::string& v) {
        bool ok = true;
        if (k == "kind") {
            if (v == "linear")
                a.kind = AxisKind::Linear;
            else if (v == "rotary")
                a.kind = AxisKind::Rotary;
            else
                ok = false;
        } else if (k == "definition") {
            a.definitions = splitWords(v, ',');
            ok = !a.definitions.empty() && a.definitions.size() <= 4;
        } else if (k == "designation2")
            a.designation2 = v;
        else if (k == "polar_direction")
            ok = parseInt(v, a.polarDirection) && (a.polarDirection == 0 || a.polarDirection == 1);
        else if (k == "min")
            ok = parseDouble(v, a.minPosition);
        else if (k == "max")
            ok = parseDouble(v, a.maxPosition);
        else if (k == "max_velocity")
            ok = parseDouble(v, a.maxVelocity) && a.maxVelocity > 0;
        else if (k == "max_acceleration")
            ok = parseDouble(v, a.maxAcceleration) && a.maxAcceleration > 0;
        else if (k == "index")
            ok = parseInt(v, a.spindleIndex) && a.spindleIndex >= 1 && a.spindleIndex <= 3;
        else if (k == "rotary_axis")
            a.rotaryAxisName = v;
        else if (k == "max_speed")
            ok = parseDouble(v, a.maxSpeed) && a.maxSpeed >= 0;
        else
            return error("CFG_KEY", "unknown axis key '" + k + "'");
        if (!ok) error("CFG_VALUE", "bad value '" + v + "' for axis key '" + k + "'");
    }

    void openMGroup(ProcessConfig& p, const std::string& number) {
        int n = 0;
        if (!parseInt(number, n) || n < 1 || n > 15)
            return error("CFG_MGROUP", "M group number must be 1..15, got '" + number + "'");
        p.mGroups.push_back({});
        p.mGroups.back().number = n;
        const int process = p.index;
        const size_t slot = p.mGroups.size() - 1;
        handler_ = [this, process, slot](const std::string& k, const std::string& v) {
            MGroupConfig& g = r_.config.processes[indexOf(process)].mGroups[slot];
            if (k == "name") return void(g.name = v);
            if (k == "reset") {
                if (!parseInt(v, g.resetValue)) error("CFG_VALUE", "bad reset value '" + v + "'");
                return;
            }
            if (k != "functions") return error("CFG_KEY", "unknown M group key '" + k + "'");
            for (const auto& w : splitWords(v)) {
                int m = 0;
                if (!parseInt(w, m) || m < 0 || m > 999)
                    error("CFG_VALUE", "bad M function '" + w + "'");
                else
                    g.functions.push_back(m);
            }
        };
    }

    /// `[process N torque-model]`: numeric constants of the simulated
    /// reference axis of adaptive feed control (TorqueModelParameters).
    void openTorqueModel(ProcessConfig& p) {
        const int process = p.index;
        handler_ = [this, process](const std::string& k, const std::string& v) {
            static const char* const kKeys[] = {
                "stall",    "friction_rest", "friction_max", "cutting", "reference_feed",
                "exponent", "load",          "noise",        "seed",    "engagement"};
            bool known = false;
            for (const char* key : kKeys)
                known = known || k == key;
            double value = 0;
            if (!known) return error("CFG_TORQUE_MODEL", "unknown torque model key '" + k + "'");
            if (!parseDouble(v, value) || value < -1000 || value > 1e9)
                return error("CFG_TORQUE_MODEL", "torque model '" + k + "' needs a number");
            r_.config.processes[indexOf(process)].torqueModel[k] = value;
        };
    }

    void openTools(ProcessConfig& p) {
        const int process = p.index;
        handler_ = [this, process](const std::string& k, const std::string& v) {
            ProcessConfig& proc = r_.config.processes[indexOf(process)];
            ToolConfig tool;
            if (k.size() < 2 || k[0] != 'T' || !parseInt(k.substr(1), tool.number) ||
                tool.number <= 0)
                return error("CFG_TOOL", "tool key must be T<number>, got '" + k + "'");
            auto words = splitWords(v);
            for (size_t i = 0; i + 1 < words.size(); i += 2) {
                bool ok = true;
                if (words[i] == "radius")
                    ok = parseDouble(words[i + 1], tool.radius);
                else if (words[i] == "length")
                    ok = parseDouble(words[i + 1], tool.length);
                else if (words[i] == "edge")
                    ok = parseInt(words[i + 1], tool.edgeOrientation);
                else if (words[i] == "name")
                    tool.name = words[i + 1];
                else
                    ok = false;
                if (!ok) error("CFG_TOOL", "bad tool data '" + words[i] + " " + words[i + 1] + "'");
            }
            if (words.size() % 2 != 0) error("CFG_TOOL", "tool data must be pairs of 'key value'");
            if (proc.tool(tool.number)) return error("CFG_TOOL", "tool " + k + " defined twice");
            proc.tools.push_back(tool);
        };
    }

    void openZeroOffsets(ProcessConfig& p) {
        const int process = p.index;
        handler_ = [this, process](const std::string& k, const std::string& v) {
            ZeroOffset offset;
            offset.code = k;
            for (const auto& w : splitWords(v)) {
                size_t split = w.find_first_of("+-0123456789.", 1);
                double value = 0;
                if (split == std::string::npos || !parseDouble(w.substr(split), value)) {
                    error("CFG_VALUE", "bad zero offset word '" + w + "'");
                    continue;
                }
                offset.values[w.substr(0, split)] = value;
            }
            r_.config.processes[indexOf(process)].zeroOffsets.push_back(offset);
        };
    }

    void openPage(ProcessConfig& p, const std::string& number) {
        UserDataPage page;
        if (!parseInt(number, page.number) || page.number < 100 || page.number > 999)
            return error("CFG_PAGE", "user page number must be 100..999, got '" + number + "'");
        p.userPages.push_back(page);
        const int process = p.index;
        const size_t slot = p.userPages.size() - 1;
        handler_ = [this, process, slot](const std::string& k, const std::string& v) {
            UserDataPage& pg = r_.config.processes[indexOf(process)].userPages[slot];
            if (k == "title") return void(pg.title = v);
            UserDataElement e;
            auto fields = splitWords(v, '|');
            if (k.rfind("element ", 0) != 0 || !parseInt(trim(k.substr(8)), e.number) ||
                fields.size() < 5 || fields.size() > 7)
                return error("CFG_PAGE",
                             "expected 'element N = designation | type | min | max | default "
                             "[| unit [| protection]]'");
            e.designation = fields[0];
            e.type = fields[1];
            if (!knownDataType(e.type))
                return error("CFG_PAGE", "unknown data type '" + e.type +
                                             "' (BOOL SINT UINT AMPL PERC INT REAL)");
            if (!parseDouble(fields[2], e.minimum) || !parseDouble(fields[3], e.maximum) ||
                !parseDouble(fields[4], e.defaultValue) || e.minimum > e.maximum ||
                e.defaultValue < e.minimum || e.defaultValue > e.maximum)
                return error("CFG_PAGE", "bad range or default in element " + trim(k.substr(8)));
            if (fields.size() > 5 && fields[5] != "-") e.unit = fields[5];
            if (fields.size() > 6 && !readProtection(fields[6], e))
                return error("CFG_PAGE", "protection must list nc, sps, gui, password; got '" +
                                             fields[6] + "'");
            pg.elements.push_back(e);
        };
    }

    static bool knownDataType(const std::string& type) {
        for (const char* name : {"BOOL", "SINT", "UINT", "AMPL", "PERC", "INT", "REAL"})
            if (type == name) return true;
        return false;
    }

    /// "nc sps gui password" (any subset, blank-separated) into the flags.
    static bool readProtection(const std::string& text, UserDataElement& e) {
        for (const std::string& word : splitWords(text)) {
            if (word == "nc")
                e.protectedNc = true;
            else if (word == "sps")
                e.protectedSps = true;
            else if (word == "gui")
                e.protectedGui = true;
            else if (word == "password")
                e.password = true;
            else
                return false;
        }
        return true;
    }

    MachineConfigReadResult& r_;
    int line_ = 0;
    std::function<void(const std::string&, const std::string&)> handler_;
};

}  // namespace

MachineConfigReadResult readMachineConfig(std::string_view text) {
    MachineConfigReadResult result;
    Reader(result).run(text);
    return result;
}

}  // namespace mtc::core
