// The sections whose keys are not names of the rule table: the tools list
// (T<n> = ...), the zero offsets (G54 = X... Y...) and user machine data
// pages (element E = ... | ... ). Their parts are checked with the table's
// rules all the same (docs/MACHINE-CONFIG.md, "Value ranges").
#include <unordered_map>

#include "cnc_core/machine/ConfigSections.h"
#include "cnc_core/machine/ConfigText.h"
#include "cnc_core/machine/ConfigWords.h"

namespace mtc::core {
namespace {

class ToolsReader : public ConfigSectionReader {
  public:
    ToolsReader(ConfigReport& report, ProcessConfig& process)
        : ConfigSectionReader(report, ConfigSection::Tools),
          process_(process),
          tool_(rule("T<n>")),
          fields_{&rule("radius"), &rule("length"), &rule("edge"), &rule("name")} {}

    void line(std::string_view key, std::string_view value) override {
        double number = 0.0;
        if (key.size() < 2 || key[0] != 'T' ||
            readWholeNumber(key.substr(1), number) != NumberProblem::None ||
            number < tool_.minimum || number > tool_.maximum)
            return report_.error("CFG_TOOL", "key " + quotedValue(key) +
                                                 " is not a tool number; allowed: " +
                                                 configRangeText(tool_));
        const int toolNumber = static_cast<int>(number);
        const auto [first, inserted] = lines_.emplace(toolNumber, report_.line());
        if (!inserted)
            return report_.error("CFG_DUPLICATE", "T" + std::to_string(toolNumber) +
                                                      " is given twice (first in line " +
                                                      std::to_string(first->second) + ")");
        ToolConfig tool;
        tool.number = toolNumber;
        if (readFields(key, value, tool)) process_.tools.push_back(std::move(tool));
    }

  protected:
    void apply(const ConfigRule&, const ConfigValue&) override {}

  private:
    /// "radius R length L [edge E] [name WORD]" into `tool`; false after a report.
    bool readFields(std::string_view key, std::string_view value, ToolConfig& tool) {
        const std::vector<std::string_view> words = splitConfigWords(value);
        if (words.empty() || words.size() % 2 != 0)
            return report_.valueError("CFG_TOOL", key, value,
                                      words.empty() ? "is empty" : "is not pairs of 'field value'",
                                      &tool_),
                   false;
        bool given[4] = {false, false, false, false};
        for (std::size_t i = 0; i < words.size(); i += 2) {
            std::size_t f = 0;
            while (f < 4 && fields_[f]->key != words[i])
                ++f;
            if (f == 4 || given[f])
                return report_.valueError("CFG_TOOL", key, value,
                                          (f == 4 ? "has an unknown field " : "repeats the field ") +
                                              quotedValue(words[i]),
                                          &tool_),
                       false;
            given[f] = true;
            ConfigValue v;
            std::string problem;
            if (!checkConfigValue(*fields_[f], words[i + 1], v, problem))
                return report_.valueError("CFG_TOOL", key, value,
                                          "has " + std::string(words[i]) + " " +
                                              quotedValue(words[i + 1]) + " that " + problem,
                                          fields_[f]),
                       false;
            if (f == 0) tool.radius = v.number;
            if (f == 1) tool.length = v.number;
            if (f == 2) tool.edgeOrientation = static_cast<int>(v.number);
            if (f == 3) tool.name = v.text;
        }
        if (!given[0] || !given[1])
            return report_.valueError("CFG_TOOL", key, value, "needs radius and length", &tool_),
                   false;
        return true;
    }

    ProcessConfig& process_;
    const ConfigRule& tool_;
    const ConfigRule* fields_[4];
    std::unordered_map<int, int> lines_;  ///< tool number -> line
};

class ZeroOffsetsReader : public ConfigSectionReader {
  public:
    ZeroOffsetsReader(ConfigReport& report, ProcessConfig& process)
        : ConfigSectionReader(report, ConfigSection::ZeroOffsets),
          process_(process),
          code_(rule("code")),
          axis_(rule("axis")),
          value_(rule("value")) {}

    void line(std::string_view key, std::string_view value) override {
        ConfigValue code;
        std::string problem;
        if (!checkConfigValue(code_, key, code, problem))
            return report_.error("CFG_ZERO_OFFSET", "key " + quotedValue(key) +
                                                        " is not a zero offset; allowed: " +
                                                        configRangeText(code_));
        if (!firstUse(code.text)) return;
        const std::vector<std::string_view> words = splitConfigWords(value);
        if (words.empty()) return report_.valueError(valueCode(), key, value, "is empty", &value_);
        ZeroOffset offset;
        offset.code = code.text;
        offset.line = report_.line();
        for (std::string_view word : words) {
            ConfigValue column, number;
            if (!checkConfigValue(axis_, word.substr(0, 1), column, problem))
                return report_.valueError(valueCode(), key, value,
                                          "has " + quotedValue(word) +
                                              " that does not start with an axis definition",
                                          &axis_);
            if (!checkConfigValue(value_, word.substr(1), number, problem))
                return report_.valueError(valueCode(), key, value,
                                          "has " + column.text + " " + quotedValue(word.substr(1)) +
                                              " that " + problem,
                                          &value_);
            if (!offset.values.emplace(column.text, number.number).second)
                return report_.valueError(valueCode(), key, value,
                                          "gives column " + column.text + " twice", &axis_);
        }
        process_.zeroOffsets.push_back(std::move(offset));
    }

  protected:
    void apply(const ConfigRule&, const ConfigValue&) override {}

  private:
    ProcessConfig& process_;
    const ConfigRule& code_;
    const ConfigRule& axis_;
    const ConfigRule& value_;
};

/// The limits of a machine data type (MachineDataType.h) for min, max and default.
struct TypeLimits {
    const char* type;
    double minimum, maximum;
    bool whole;
};

constexpr TypeLimits kTypeLimits[] = {
    {"BOOL", 0, 1, true},        {"SINT", -128, 127, true},
    {"UINT", 0, 65535, true},    {"INT", -2147483648.0, 2147483647.0, true},
    {"AMPL", -1e15, 1e15, false}, {"PERC", -1e15, 1e15, false},
    {"REAL", -1e15, 1e15, false},
};

class PageReader : public ConfigSectionReader {
  public:
    PageReader(ConfigReport& report, UserDataPage& page)
        : ConfigSectionReader(report, ConfigSection::Page), page_(page) {}

    void line(std::string_view key, std::string_view value) override {
        if (key.substr(0, 8) != "element " && key != "element")
            return ConfigSectionReader::line(key, value);
        const ConfigRule& numberRule = rule("element");
        ConfigValue number;
        if (!check(numberRule, "element", trimConfigText(key.substr(7)), number) ||
            !firstUse("element " + formatConfigNumber(number.number)))
            return;
        UserDataElement element;
        element.number = static_cast<int>(number.number);
        if (readElement(key, value, element)) page_.elements.push_back(std::move(element));
    }

  protected:
    void apply(const ConfigRule& rule, const ConfigValue& value) override {
        if (rule.key == "title") page_.title = value.text;
    }

  private:
    bool readElement(std::string_view key, std::string_view value, UserDataElement& e) {
        std::vector<std::string_view> fields = splitConfigFields(value, '|');
        if (fields.size() > 1 && fields.back().empty()) fields.pop_back();  // a closing '|'
        if (fields.size() < 5 || fields.size() > 7)
            return report_.error("CFG_PAGE",
                                 std::string(key) + " = " + quotedValue(value) +
                                     " needs 'designation | type | min | max | default [| unit "
                                     "[| protection]]'"),
                   false;
        ConfigValue designation, type, minimum, maximum, preset;
        const ConfigRule& limit = rule("limit");
        if (!field(key, value, "designation", fields[0], designation) ||
            !field(key, value, "type", fields[1], type) ||
            !field(key, value, "min", fields[2], minimum, &limit) ||
            !field(key, value, "max", fields[3], maximum, &limit) ||
            !field(key, value, "default", fields[4], preset, &limit))
            return false;
        e.designation = designation.text;
        e.type = type.text;
        e.minimum = minimum.number;
        e.maximum = maximum.number;
        e.defaultValue = preset.number;
        if (!fitType(key, value, e)) return false;
        if (fields.size() > 5 && fields[5] != "-") {
            ConfigValue unit;
            if (!field(key, value, "unit", fields[5], unit)) return false;
            e.unit = unit.text;
        }
        if (fields.size() > 6 && !readProtection(fields[6], e))
            return report_.valueError("CFG_PAGE", key, value,
                                      "has the protection " + quotedValue(fields[6]),
                                      &rule("protection")),
                   false;
        return true;
    }

    /// Checks field `name` of an element line against its rule (`rule`, or
    /// the rule of that name); a refusal names the line's key and whole value.
    bool field(std::string_view key, std::string_view value, const char* name,
               std::string_view text, ConfigValue& out, const ConfigRule* rule = nullptr) {
        const ConfigRule& r = rule ? *rule : this->rule(name);
        std::string problem;
        if (checkConfigValue(r, text, out, problem)) return true;
        report_.valueError("CFG_PAGE", key, value,
                           "has the " + std::string(name) + " " + quotedValue(text) + " that " +
                               problem,
                           &r);
        return false;
    }

    /// min <= default <= max inside the limits of the type, whole for whole types.
    bool fitType(std::string_view key, std::string_view value, const UserDataElement& e) {
        for (const TypeLimits& t : kTypeLimits) {
            if (e.type != t.type) continue;
            for (double v : {e.minimum, e.maximum, e.defaultValue}) {
                if (v >= t.minimum && v <= t.maximum && (!t.whole || v == static_cast<long long>(v)))
                    continue;
                report_.error("CFG_PAGE", std::string(key) + " = " + quotedValue(value) + ": " +
                                              formatConfigNumber(v) + " does not fit type " +
                                              e.type + "; allowed: " +
                                              formatConfigNumber(t.minimum) + " … " +
                                              formatConfigNumber(t.maximum) +
                                              (t.whole ? " (whole)" : ""));
                return false;
            }
        }
        if (e.minimum <= e.defaultValue && e.defaultValue <= e.maximum) return true;
        report_.error("CFG_PAGE", std::string(key) + " = " + quotedValue(value) + ": min " +
                                      formatConfigNumber(e.minimum) +
                                      ", max " + formatConfigNumber(e.maximum) + ", default " +
                                      formatConfigNumber(e.defaultValue) +
                                      ": allowed: min ≤ default ≤ max");
        return false;
    }

    /// "nc sps gui password" (any subset, blank-separated) into the flags.
    static bool readProtection(std::string_view text, UserDataElement& e) {
        for (std::string_view word : splitConfigWords(text)) {
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

    UserDataPage& page_;
};

}  // namespace

std::unique_ptr<ConfigSectionReader> makeToolsReader(ConfigReport& report, ProcessConfig& process) {
    return std::make_unique<ToolsReader>(report, process);
}

std::unique_ptr<ConfigSectionReader> makeZeroOffsetsReader(ConfigReport& report,
                                                           ProcessConfig& process) {
    return std::make_unique<ZeroOffsetsReader>(report, process);
}

std::unique_ptr<ConfigSectionReader> makePageReader(ConfigReport& report, UserDataPage& page) {
    return std::make_unique<PageReader>(report, page);
}

}  // namespace mtc::core
