#include "cnc_core/machine/ConfigSections.h"

#include <algorithm>

#include "cnc_core/machine/AxisName.h"
#include "cnc_core/machine/ConfigText.h"
#include "cnc_core/machine/ConfigWords.h"
#include "cnc_core/toolpath/Stock.h"

namespace mtc::core {

// ---------------------------------------------------------------- base

void ConfigSectionReader::line(std::string_view key, std::string_view value) {
    const ConfigRule* found = findConfigRule(kind_, key);
    if (!found || found->key.front() == '(') return unknownKey(key);
    if (!firstUse(key)) return;
    ConfigValue checked;
    if (check(*found, key, value, checked)) apply(*found, checked);
}

bool ConfigSectionReader::firstUse(std::string_view key) {
    const auto [it, inserted] = seen_.emplace(std::string(key), report_.line());
    if (inserted) return true;
    report_.error("CFG_DUPLICATE", std::string(key) + " is given twice (first in line " +
                                       std::to_string(it->second) +
                                       "); each key once per section");
    return false;
}

bool ConfigSectionReader::check(const ConfigRule& rule, std::string_view key,
                                std::string_view text, ConfigValue& value) {
    std::string problem;
    if (checkConfigValue(rule, text, value, problem)) return true;
    report_.valueError(valueCode(), key, text, problem, &rule);
    return false;
}

void ConfigSectionReader::unknownKey(std::string_view key) {
    std::string known;
    for (const ConfigRule& r : configRules())
        if (r.section == kind_ && r.key.front() != '(')
            known += (known.empty() ? "" : ", ") + std::string(r.key);
    const bool parameter = kind_ == ConfigSection::Process && key.size() > 1 && key[0] == 'B';
    report_.error(kind_ == ConfigSection::TorqueModel ? "CFG_TORQUE_MODEL" : "CFG_KEY",
                  std::string(parameter ? "unknown process parameter " : "unknown key ") +
                      quotedValue(key) + "; known: " + known);
}

std::string_view ConfigSectionReader::valueCode() const {
    switch (kind_) {
        case ConfigSection::Tools: return "CFG_TOOL";
        case ConfigSection::TorqueModel: return "CFG_TORQUE_MODEL";
        case ConfigSection::Page: return "CFG_PAGE";
        case ConfigSection::ZeroOffsets: return "CFG_ZERO_OFFSET";
        default: return "CFG_VALUE";
    }
}

const ConfigRule& ConfigSectionReader::rule(std::string_view key) const {
    return *findConfigRule(kind_, key);
}

namespace {

// ---------------------------------------------------------------- sections

class SkippedSection : public ConfigSectionReader {
  public:
    explicit SkippedSection(ConfigReport& report) : ConfigSectionReader(report, ConfigSection::Cell) {}
    void line(std::string_view, std::string_view) override {}

  protected:
    void apply(const ConfigRule&, const ConfigValue&) override {}
};

class CellReader : public ConfigSectionReader {
  public:
    CellReader(ConfigReport& report, MachineConfig& cell)
        : ConfigSectionReader(report, ConfigSection::Cell), cell_(cell) {}

  protected:
    void apply(const ConfigRule& rule, const ConfigValue& value) override {
        if (rule.key == "name") cell_.name = value.text;
        if (rule.key == "md_password") cell_.machineDataPassword = value.text;
    }

  private:
    MachineConfig& cell_;
};

class ProcessReader : public ConfigSectionReader {
  public:
    ProcessReader(ConfigReport& report, ProcessConfig& process)
        : ConfigSectionReader(report, ConfigSection::Process), process_(process) {}

  protected:
    void apply(const ConfigRule& rule, const ConfigValue& value) override {
        if (rule.key == "name")
            process_.name = value.text;
        else if (rule.key == "tool_places")
            process_.toolPlaces = static_cast<int>(value.number);
        else if (rule.key == "tool_storage")
            process_.toolStorage = value.text;
        else if (rule.key == "stock")
            readStock(rule, value.text);
        else  // Bnnn: kept as text (ProcessConfig::flag/number read it)
            process_.parameters[std::string(rule.key)] = value.text;
    }

  private:
    /// `stock = ...`: the numbers checked here, the shapes by parseStock (one rule).
    void readStock(const ConfigRule& rule, const std::string& text) {
        const std::vector<std::string_view> words = splitConfigWords(text);
        for (std::size_t i = 1; i < words.size(); ++i) {
            double number = 0.0;
            const bool axisWord = words[0] == "cylinder" && i == 1;
            const NumberProblem problem = axisWord ? NumberProblem::None
                                                   : readDecimal(words[i], number);
            if (problem != NumberProblem::None || number < rule.minimum || number > rule.maximum)
                return report_.valueError("CFG_STOCK", "stock", text,
                                          "has a word " + quotedValue(words[i]) + " that " +
                                              (problem == NumberProblem::None
                                                   ? std::string("is outside ±1e+06 mm")
                                                   : describeNumberProblem(problem)),
                                          &rule);
        }
        Stock stock;
        std::string problem;
        if (!parseStock(text, stock, problem))
            return report_.valueError("CFG_STOCK", "stock", text, "is refused: " + problem, &rule);
        process_.stock = text;
    }

    ProcessConfig& process_;
};

class AxisReader : public ConfigSectionReader {
  public:
    AxisReader(ConfigReport& report, AxisConfig& axis)
        : ConfigSectionReader(report, axis.kind == AxisKind::Spindle ? ConfigSection::Spindle
                                                                     : ConfigSection::Axis),
          axis_(axis) {}

    void finish() override {
        const double low = axis_.minPosition, high = axis_.maxPosition;
        if (low < high || (low == 0.0 && high == 0.0)) return;
        const int line = std::max(seen_.count("min") ? seen_["min"] : 0,
                                  seen_.count("max") ? seen_["max"] : 0);
        report_.errorAt(line, "CFG_VALUE",
                        "min = " + formatConfigNumber(low) + " and max = " +
                            formatConfigNumber(high) +
                            ": min must be below max (both 0 = travel not monitored)");
    }

  protected:
    void apply(const ConfigRule& rule, const ConfigValue& value) override {
        const std::string_view key = rule.key;
        if (key == "kind")
            axis_.kind = value.text == "rotary" ? AxisKind::Rotary : AxisKind::Linear;
        else if (key == "definition")
            readDefinitions(rule, value.text);
        else if (key == "designation2")
            readDesignation(rule, value.text, axis_.designation2);
        else if (key == "polar_direction")
            axis_.polarDirection = static_cast<int>(value.number);
        else if (key == "min")
            axis_.minPosition = value.number;
        else if (key == "max")
            axis_.maxPosition = value.number;
        else if (key == "max_velocity")
            axis_.maxVelocity = value.number;
        else if (key == "max_acceleration")
            axis_.maxAcceleration = value.number;
        else if (key == "index")
            axis_.spindleIndex = static_cast<int>(value.number);
        else if (key == "rotary_axis")
            readDesignation(rule, value.text, axis_.rotaryAxisName);
        else if (key == "max_speed")
            axis_.maxSpeed = value.number;
    }

  private:
    /// An axis designation ("Y1", "C"): AxisName's rule with a letter of
    /// the axis addresses X..C.
    void readDesignation(const ConfigRule& rule, const std::string& text, std::string& out) {
        const AxisName name = AxisName::parse(text);
        if (!name.valid() || definitionFromLetter(name.letter) == AxisDefinition::None)
            return report_.valueError("CFG_VALUE", rule.key, text, "is not an axis designation",
                                      &rule);
        out = text;
    }

    /// "X, Z": 1..4 definition letters; duplicates with the other axes of the
    /// process are checked with them (ProcessAxes::build).
    void readDefinitions(const ConfigRule& rule, const std::string& text) {
        std::vector<std::string> names;
        for (std::string_view field : splitConfigFields(text, ',')) {
            if (field.size() != 1 || definitionFromLetter(field[0]) == AxisDefinition::None)
                return report_.valueError("CFG_VALUE", "definition", text,
                                          "has " + quotedValue(field) +
                                              ", not an axis definition",
                                          &rule);
            names.emplace_back(field);
        }
        if (names.size() < rule.minimum || names.size() > rule.maximum)
            return report_.valueError("CFG_VALUE", "definition", text,
                                      "has " + std::to_string(names.size()) + " names", &rule);
        axis_.definitions = std::move(names);
    }

    AxisConfig& axis_;
};

class MGroupReader : public ConfigSectionReader {
  public:
    MGroupReader(ConfigReport& report, ProcessConfig& process, std::size_t group)
        : ConfigSectionReader(report, ConfigSection::MGroup), process_(process), group_(group) {}

    void finish() override {
        const MGroupConfig& g = process_.mGroups[group_];
        const auto& f = g.functions;
        if (g.resetValue != -1 && std::find(f.begin(), f.end(), g.resetValue) == f.end())
            report_.errorAt(seen_.count("reset") ? seen_["reset"] : report_.line(), "CFG_VALUE",
                            "reset = " + std::to_string(g.resetValue) +
                                " is not one of the group's functions; allowed: -1 or one of "
                                "functions");
        for (std::size_t other = 0; other < group_; ++other)
            for (int m : process_.mGroups[other].functions)
                if (std::find(f.begin(), f.end(), m) != f.end())
                    report_.errorAt(seen_["functions"], "CFG_VALUE",
                                    "M" + std::to_string(m) + " is in group " +
                                        std::to_string(g.number) + " and in group " +
                                        std::to_string(process_.mGroups[other].number) +
                                        "; an M function belongs to one group");
    }

  protected:
    void apply(const ConfigRule& rule, const ConfigValue& value) override {
        MGroupConfig& g = process_.mGroups[group_];
        if (rule.key == "name") g.name = value.text;
        if (rule.key == "reset") g.resetValue = static_cast<int>(value.number);
        if (rule.key == "functions") readFunctions(rule, value.text, g.functions);
    }

  private:
    void readFunctions(const ConfigRule& rule, const std::string& text, std::vector<int>& out) {
        std::vector<int> functions;
        for (std::string_view word : splitConfigWords(text)) {
            double m = 0.0;
            const NumberProblem problem = readWholeNumber(word, m);
            if (problem != NumberProblem::None || m < rule.minimum || m > rule.maximum)
                return report_.valueError("CFG_VALUE", "functions", text,
                                          "has " + quotedValue(word) + ", not an M number",
                                          &rule);
            if (std::find(functions.begin(), functions.end(), static_cast<int>(m)) !=
                functions.end())
                return report_.valueError("CFG_VALUE", "functions", text,
                                          "names M" + std::string(word) + " twice", &rule);
            functions.push_back(static_cast<int>(m));
        }
        out = std::move(functions);
    }

    ProcessConfig& process_;
    std::size_t group_;
};

class TorqueModelReader : public ConfigSectionReader {
  public:
    TorqueModelReader(ConfigReport& report, ProcessConfig& process)
        : ConfigSectionReader(report, ConfigSection::TorqueModel), process_(process) {}

  protected:
    void apply(const ConfigRule& rule, const ConfigValue& value) override {
        process_.torqueModel[std::string(rule.key)] = value.number;
    }

  private:
    ProcessConfig& process_;
};

}  // namespace

std::unique_ptr<ConfigSectionReader> makeSkippedSection(ConfigReport& report) {
    return std::make_unique<SkippedSection>(report);
}

std::unique_ptr<ConfigSectionReader> makeCellReader(ConfigReport& report, MachineConfig& cell) {
    return std::make_unique<CellReader>(report, cell);
}

std::unique_ptr<ConfigSectionReader> makeProcessReader(ConfigReport& report,
                                                       ProcessConfig& process) {
    return std::make_unique<ProcessReader>(report, process);
}

std::unique_ptr<ConfigSectionReader> makeAxisReader(ConfigReport& report, AxisConfig& axis) {
    return std::make_unique<AxisReader>(report, axis);
}

std::unique_ptr<ConfigSectionReader> makeMGroupReader(ConfigReport& report,
                                                      ProcessConfig& process, std::size_t group) {
    return std::make_unique<MGroupReader>(report, process, group);
}

std::unique_ptr<ConfigSectionReader> makeTorqueModelReader(ConfigReport& report,
                                                           ProcessConfig& process) {
    return std::make_unique<TorqueModelReader>(report, process);
}

}  // namespace mtc::core
