#include "cnc_core/machine/ConfigSchema.h"

#include <cctype>

#include "cnc_core/afc/AfcParameterRanges.h"
#include "cnc_core/machine/ConfigText.h"
#include "cnc_core/machine/MachineConfig.h"

namespace mtc::core {
namespace {

using S = ConfigSection;
using T = ConfigValueType;

constexpr double kTravel = 1e6;  // mm or degrees: far beyond any machine, refuses 1e308
constexpr const char* kDesignation = "X Y Z U V W A B C, optionally with index 1 … 3 (Z2)";
constexpr const char* kDefinitions = "1 … 4 of X Y Z U V W A B C, comma-separated";

/// The table. Ranges come from the seeds where they give one (seed 002 4.2
/// for Bxx.063..069, from AfcParameterRanges, seed 001 ch. 6 / lookahead.md LA-010 for B070..B072,
/// seed 003 for Cxx.076); the others are this project's limits (docs/decisions/
/// config-files.md CF-002): generous for any real machine, tight enough that no
/// value can switch a check off or make a loop or a simulated duration explode.
std::vector<ConfigRule> buildRules() {
    std::vector<ConfigRule> rules = {
        {S::Cell, "name", T::Text, 1, 80, "", "", "name of the cell (machine data file name)"},
        {S::Cell, "md_password", T::Word, 1, 32, "", "",
         "password of password-protected machine data (default MTC200)"},

        {S::Process, "(number)", T::Whole, 0, 6, "", "", "N of [process N]"},
        {S::Process, "name", T::Text, 1, 80, "", "", "name of the station"},
        {S::Process, "tool_places", T::Whole, 0, 999, "", "places", "magazine / turret places"},
        {S::Process, "tool_storage", T::Choice, 0, 0, "magazine turret", "", "tool storage"},
        {S::Process, "stock", T::Form, -kTravel, kTravel,
         "block XMIN XMAX YMIN YMAX ZMIN ZMAX | cylinder X|Y|Z RADIUS FROM TO | none", "mm",
         "raw part of the toolpath view, machine coordinates"},
        {S::Process, "B004", T::Choice, 0, 0, "17 18 19", "", "default interpolation plane"},
        {S::Process, "B015", T::Choice, 0, 0, "radius diameter", "",
         "default programming of the first linear axis"},
        {S::Process, "B033", T::Choice, 0, 0, "yes no", "", "reverse program execution required"},
        {S::Process, "B036", T::Choice, 0, 0, "yes no", "", "manual axis jogging causes reset"},
        {S::Process, "B058", T::Choice, 0, 0, "yes no", "", "M output during NC program restart"},
        {S::Process, "B059", T::Choice, 0, 0, "yes no", "", "Q output during NC program restart"},
        {S::Process, "B060", T::Choice, 0, 0, "yes no", "", "S output during NC program restart"},
        {S::Process, "B061", T::Choice, 0, 0, "yes no", "", "T/E output during NC program restart"},
        {S::Process, "B062", T::Choice, 0, 0, "yes no", "", "adaptive feed control available"},
        // B063..B069: inserted from the adaptive feed control's own table below.
        {S::Process, "B070", T::Number, 3, 30, "", "ms", "METB preset (look-ahead)"},
        {S::Process, "B071", T::Number, 1, 10, "", "", "VFBT preset (look-ahead)"},
        {S::Process, "B072", T::Whole, 1, 10, "", "", "BBTRC preset (look-ahead)"},
        {S::Process, "B073", T::Number, 0.5, 30, "", "ms", "NC block cycle time"},
        {S::Process, "B074", T::Number, 100, 200, "", "%", "maximum of the feed override"},

        {S::Axis, "kind", T::Choice, 0, 0, "linear rotary", "", "linear or rotary axis"},
        {S::Axis, "definition", T::Form, 1, 4, kDefinitions, "",
         "Cxx.053: base definition, then G20 alternates"},
        {S::Axis, "designation2", T::Form, 0, 0, kDesignation, "", "Cxx.075, used under G31/G32"},
        {S::Axis, "polar_direction", T::Whole, 0, 1, "", "", "Cxx.076"},
        {S::Axis, "min", T::Number, -kTravel, kTravel, "", "mm | deg",
         "lower travel limit (min < max; both 0 = not monitored)"},
        {S::Axis, "max", T::Number, -kTravel, kTravel, "", "mm | deg", "upper travel limit"},
        {S::Axis, "max_velocity", T::Number, 1, 1e7, "", "mm/min | deg/min", "maximum velocity"},
        {S::Axis, "max_acceleration", T::Number, 1, 1e6, "", "mm/s² | deg/s²",
         "maximum acceleration"},

        {S::Spindle, "index", T::Whole, 1, 3, "", "", "1..3 for S1..S3"},
        {S::Spindle, "rotary_axis", T::Form, 0, 0, kDesignation, "",
         "name in rotary axis mode (e.g. C)"},
        {S::Spindle, "definition", T::Form, 1, 4, kDefinitions, "", "Cxx.053 in rotary axis mode"},
        {S::Spindle, "designation2", T::Form, 0, 0, kDesignation, "", "Cxx.075"},
        {S::Spindle, "polar_direction", T::Whole, 0, 1, "", "", "Cxx.076"},
        {S::Spindle, "max_speed", T::Number, 1, 100000, "", "rpm", "maximum speed"},
        {S::Spindle, "max_velocity", T::Number, 1, 1e7, "", "deg/min",
         "maximum velocity in rotary axis mode"},
        {S::Spindle, "max_acceleration", T::Number, 1, 1e6, "", "deg/s²",
         "maximum acceleration in rotary axis mode"},

        {S::MGroup, "(number)", T::Whole, 1, 15, "", "", "G of [process N mgroup G]"},
        {S::MGroup, "name", T::Text, 1, 80, "", "", "name of the group"},
        {S::MGroup, "functions", T::Form, 0, 999,
         "M numbers 0 … 999, blank-separated, each in one group only", "", "M functions"},
        {S::MGroup, "reset", T::Whole, -1, 999, "", "",
         "value at power-on / program end: -1 or one of the group's functions"},

        {S::Tools, "T<n>", T::Form, 1, 9999999,
         "T1 … T9999999 = radius R length L [edge E] [name WORD]", "", "one tool"},
        {S::Tools, "radius", T::Number, 0, 1000, "", "mm", "tool radius"},
        {S::Tools, "length", T::Number, 0, 10000, "", "mm", "tool length"},
        {S::Tools, "edge", T::Whole, 0, 9, "", "", "cutting edge position (turning tools)"},
        {S::Tools, "name", T::Word, 1, 32, "", "", "tool name"},

        {S::ZeroOffsets, "code", T::Choice, 0, 0, "G54 G55 G56 G57 G58 G59", "",
         "the key of a line: which zero offset"},
        {S::ZeroOffsets, "axis", T::Choice, 0, 0, "X Y Z U V W A B C", "",
         "column (axis definition) of a word, each at most once per line"},
        {S::ZeroOffsets, "value", T::Number, -kTravel, kTravel, "", "mm | deg",
         "the number after the column letter"},

        {S::TorqueModel, "stall", T::Number, -500, 500, "", "%", "weight torque (signed)"},
        {S::TorqueModel, "friction_rest", T::Number, 0, 500, "", "%", "idling torque at creep"},
        {S::TorqueModel, "friction_max", T::Number, 0, 500, "", "%",
         "idling torque at maximum speed"},
        {S::TorqueModel, "cutting", T::Number, 0, 500, "", "%",
         "cutting torque at full engagement and reference_feed"},
        {S::TorqueModel, "reference_feed", T::Number, 1, 1e6, "", "mm/min", "reference feed"},
        {S::TorqueModel, "exponent", T::Number, 0, 5, "", "", "feed exponent of the cut"},
        {S::TorqueModel, "load", T::Number, 0, 500, "", "%", "constant extra load"},
        {S::TorqueModel, "noise", T::Number, 0, 100, "", "%", "noise amplitude (±)"},
        {S::TorqueModel, "seed", T::Whole, 0, 4294967295.0, "", "", "noise sequence"},
        {S::TorqueModel, "engagement", T::Number, 0, 10, "", "",
         "tool engagement where the tool is in the raw part (1 = full cut)"},

        {S::Page, "(number)", T::Whole, 100, 999, "", "", "P of [process N page P]"},
        {S::Page, "title", T::Text, 1, 80, "", "", "page title"},
        {S::Page, "element", T::Whole, 1, 999, "", "",
         "E of `element E = designation | type | min | max | default [| unit [| protection]]`"},
        {S::Page, "designation", T::Text, 1, 80, "", "", "element designation"},
        {S::Page, "type", T::Choice, 0, 0, "BOOL SINT UINT AMPL PERC INT REAL", "", "data type"},
        {S::Page, "limit", T::Number, -1e15, 1e15, "", "",
         "min, max and default: min ≤ default ≤ max, inside the type (BOOL 0 … 1, SINT -128 … "
         "127, UINT 0 … 65535, INT -2147483648 … 2147483647; whole types whole)"},
        {S::Page, "unit", T::Word, 1, 16, "", "", "unit shown (`-` = none)"},
        {S::Page, "protection", T::Form, 0, 0, "any of: nc sps gui password", "",
         "write protection"},
    };
    // Seed 002 4.2: one table of the adaptive feed control's ranges, used by
    // its own reader (AfcSettings) and by the schema, after B062.
    auto at = rules.begin();
    while (at != rules.end() && !(at->section == S::Process && at->key == "B062"))
        ++at;
    if (at != rules.end()) ++at;
    std::vector<ConfigRule> afc;
    for (const AfcParameterRange* r = afcParameterRangesBegin(); r != afcParameterRangesEnd(); ++r)
        afc.push_back({S::Process, r->key, r->whole ? T::Whole : T::Number, r->minimum,
                       r->maximum, "", r->unit, r->meaning});
    rules.insert(at, afc.begin(), afc.end());
    return rules;
}

bool sameWord(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

/// The word of `choices` that `text` names (any case), or "".
std::string_view matchingChoice(std::string_view choices, std::string_view text) {
    std::size_t start = 0;
    while (start < choices.size()) {
        std::size_t end = choices.find(' ', start);
        if (end == std::string_view::npos) end = choices.size();
        const std::string_view word = choices.substr(start, end - start);
        if (sameWord(word, text)) return word;
        start = end + 1;
    }
    return {};
}

std::string choicesText(std::string_view choices) {
    std::string text;
    for (char c : choices)
        text += c == ' ' ? std::string(" | ") : std::string(1, c);
    return text;
}

/// Text length in characters (UTF-8 lead bytes).
std::size_t characters(std::string_view text) {
    std::size_t count = 0;
    for (char c : text)
        count += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return count;
}

}  // namespace

const std::vector<ConfigRule>& configRules() {
    static const std::vector<ConfigRule> rules = buildRules();
    return rules;
}

const ConfigRule* findConfigRule(ConfigSection section, std::string_view key) {
    for (const ConfigRule& rule : configRules())
        if (rule.section == section && rule.key == key) return &rule;
    return nullptr;
}

std::string_view configSectionName(ConfigSection section) {
    switch (section) {
        case S::Cell: return "[cell]";
        case S::Process: return "[process N]";
        case S::Axis: return "[process N axis NAME]";
        case S::Spindle: return "[process N spindle NAME]";
        case S::MGroup: return "[process N mgroup G]";
        case S::Tools: return "[process N tools]";
        case S::ZeroOffsets: return "[process N zero-offsets]";
        case S::TorqueModel: return "[process N torque-model]";
        case S::Page: return "[process N page P]";
    }
    return "";
}

std::string configRangeText(const ConfigRule& rule) {
    const std::string unit = rule.unit.empty() ? "" : " " + std::string(rule.unit);
    switch (rule.type) {
        case T::Number:
        case T::Whole:
            return formatConfigNumber(rule.minimum) + " … " + formatConfigNumber(rule.maximum) +
                   unit + (rule.type == T::Whole ? " (whole)" : "");
        case T::Choice: return choicesText(rule.choices);
        case T::Text:
            return "text of " + formatConfigNumber(rule.minimum) + " … " +
                   formatConfigNumber(rule.maximum) + " characters";
        case T::Word:
            return "one word of " + formatConfigNumber(rule.minimum) + " … " +
                   formatConfigNumber(rule.maximum) + " characters";
        case T::Form:
            return std::string(rule.choices) +
                   (rule.unit.empty() ? "" : " (" + std::string(rule.unit) + ")");
    }
    return "";
}

bool checkConfigValue(const ConfigRule& rule, std::string_view text, ConfigValue& value,
                      std::string& problem) {
    if (text.empty()) return problem = "is empty", false;
    if (!isPrintableText(text))
        return problem = "contains control characters or bytes that are not UTF-8", false;
    switch (rule.type) {
        case T::Number:
        case T::Whole: {
            const NumberProblem p = rule.type == T::Whole ? readWholeNumber(text, value.number)
                                                          : readDecimal(text, value.number);
            if (p != NumberProblem::None) return problem = describeNumberProblem(p), false;
            if (value.number < rule.minimum || value.number > rule.maximum)
                return problem = "is outside the range", false;
            break;
        }
        case T::Choice: {
            std::string_view choice = matchingChoice(rule.choices, text);
            bool yes = false;  // AFC-023: a yes/no flag also takes 1/0 and true/false
            if (choice.empty() && rule.choices == std::string_view("yes no") &&
                parseYesNo(std::string(text), yes))
                choice = yes ? "yes" : "no";
            if (choice.empty()) return problem = "is not one of the allowed words", false;
            value.text = std::string(choice);
            return true;
        }
        case T::Text:
        case T::Word: {
            const std::size_t length = characters(text);
            if (rule.type == T::Word && text.find_first_of(" \t") != std::string_view::npos)
                return problem = "is more than one word", false;
            if (length < rule.minimum || length > rule.maximum)
                return problem = "has " + std::to_string(length) + " characters", false;
            break;
        }
        case T::Form: break;
    }
    value.text = std::string(text);
    return true;
}

std::string configRulesMarkdown() {
    std::string text = "| section | key | allowed | meaning |\n|---|---|---|---|\n";
    for (const ConfigRule& rule : configRules()) {
        std::string range = configRangeText(rule);
        std::string escaped;
        for (char c : range)
            escaped += c == '|' ? std::string("\\|") : std::string(1, c);
        std::string meaning;
        for (char c : rule.meaning)
            meaning += c == '|' ? std::string("\\|") : std::string(1, c);
        text += "| `" + std::string(configSectionName(rule.section)) + "` | `" +
                std::string(rule.key) + "` | " + escaped + " | " + meaning + " |\n";
    }
    return text;
}

}  // namespace mtc::core
