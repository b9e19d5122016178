#pragma once

#include <string>
#include <string_view>
#include <vector>

/// The rules of every value of the machine configuration (docs/MACHINE-CONFIG.md,
/// "Value ranges", which a test checks against this table): one table, read
/// by the configuration reader, by the adaptive feed control's parameters
/// and by the documentation test.
namespace mtc::core {

/// The kinds of section of the machine configuration.
enum class ConfigSection {
    Cell,         ///< [cell]
    Process,      ///< [process N]
    Axis,         ///< [process N axis NAME]
    Spindle,      ///< [process N spindle NAME]
    MGroup,       ///< [process N mgroup G]
    Tools,        ///< [process N tools]: fields of a `T<n> = ...` entry
    ZeroOffsets,  ///< [process N zero-offsets]: `G54..G59 = <axis><value> ...`
    TorqueModel,  ///< [process N torque-model]
    Page,         ///< [process N page P]
};

/// How a value is read.
enum class ConfigValueType {
    Number,  ///< finite decimal number inside minimum..maximum
    Whole,   ///< whole number inside minimum..maximum
    Choice,  ///< one of the words in `choices` (case-insensitive)
    Text,    ///< printable text (UTF-8, no control characters), 1..maximum characters
    Word,    ///< like Text, without blanks
    Form,    ///< a value with its own structure, checked by the reader (`choices` says which)
};

/// One key of a section and what it accepts.
struct ConfigRule {
    ConfigSection section;
    std::string_view key;  ///< "max_velocity", "B064", "radius" (a field of T<n>)
    ConfigValueType type;
    double minimum = 0.0;
    double maximum = 0.0;
    std::string_view choices;  ///< Choice: blank-separated words; Form: its syntax
    std::string_view unit;     ///< "mm/min", "%", "" = none
    std::string_view meaning;  ///< short description for the documentation
};

/// Every rule, in documentation order.
const std::vector<ConfigRule>& configRules();

/// The rule of `key` in a section of kind `section`, or nullptr (unknown key).
const ConfigRule* findConfigRule(ConfigSection section, std::string_view key);

/// "[cell]", "[process N axis NAME]", ...: how the documentation names a section kind.
std::string_view configSectionName(ConfigSection section);

/// The allowed values as text: "1 … 10000000 mm/min", "yes | no", "1 … 200 characters".
std::string configRangeText(const ConfigRule& rule);

/// A checked value: the number (Number, Whole) or the text (the choice in
/// lower case for Choice; as written otherwise).
struct ConfigValue {
    double number = 0.0;
    std::string text;
};

/// Checks `text` against `rule` (type, finiteness, range, choices). False
/// with `problem` ("is not a finite number", "is outside 1 … 100 %") when it
/// does not fit; Form rules only check that the text is printable and not empty.
bool checkConfigValue(const ConfigRule& rule, std::string_view text, ConfigValue& value,
                      std::string& problem);

/// The "Value ranges" table of docs/MACHINE-CONFIG.md as Markdown, built
/// from configRules(); the documentation test compares it with the file.
std::string configRulesMarkdown();

}  // namespace mtc::core
