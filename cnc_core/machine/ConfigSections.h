#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>

#include "cnc_core/machine/ConfigReport.h"
#include "cnc_core/machine/ConfigSchema.h"
#include "cnc_core/machine/MachineConfig.h"

/// The readers of the sections of a machine configuration (used by
/// MachineConfigReader.cpp): each gets the `key = value` lines of one
/// section, checks every value against configRules() and fills its part of
/// the MachineConfig; finish() runs the checks that need the whole section.
namespace mtc::core {

class ConfigSectionReader {
  public:
    ConfigSectionReader(ConfigReport& report, ConfigSection kind) : report_(report), kind_(kind) {}
    virtual ~ConfigSectionReader() = default;

    /// One `key = value` line (key and value trimmed). The default reads a
    /// key of the table: refuses duplicates, unknown keys and bad values,
    /// hands a good value to apply().
    virtual void line(std::string_view key, std::string_view value);
    /// The section ended (next header, [end] or end of text).
    virtual void finish() {}

  protected:
    virtual void apply(const ConfigRule& rule, const ConfigValue& value) = 0;

    /// False (CFG_DUPLICATE, naming the first line) when `key` was given before in this section.
    bool firstUse(std::string_view key);
    /// checkConfigValue() with the refusal reported; true when `text` fits.
    bool check(const ConfigRule& rule, std::string_view key, std::string_view text,
               ConfigValue& value);
    /// CFG_KEY (or the section's code) naming the keys the section knows.
    void unknownKey(std::string_view key);
    /// The code of a bad value in this section ("CFG_VALUE", "CFG_TOOL", ...).
    std::string_view valueCode() const;
    /// The rule `key` of this section (the table has it: a missing one is a programming error).
    const ConfigRule& rule(std::string_view key) const;

    ConfigReport& report_;
    ConfigSection kind_;
    std::unordered_map<std::string, int> seen_;  ///< key -> line
};

/// A section whose header was refused: its lines are skipped without a word.
std::unique_ptr<ConfigSectionReader> makeSkippedSection(ConfigReport& report);
std::unique_ptr<ConfigSectionReader> makeCellReader(ConfigReport& report, MachineConfig& cell);
std::unique_ptr<ConfigSectionReader> makeProcessReader(ConfigReport& report,
                                                       ProcessConfig& process);
std::unique_ptr<ConfigSectionReader> makeAxisReader(ConfigReport& report, AxisConfig& axis);
/// `process.mGroups[group]`; finish() also refuses an M function of another group.
std::unique_ptr<ConfigSectionReader> makeMGroupReader(ConfigReport& report,
                                                      ProcessConfig& process, std::size_t group);
std::unique_ptr<ConfigSectionReader> makeToolsReader(ConfigReport& report, ProcessConfig& process);
std::unique_ptr<ConfigSectionReader> makeZeroOffsetsReader(ConfigReport& report,
                                                           ProcessConfig& process);
std::unique_ptr<ConfigSectionReader> makeTorqueModelReader(ConfigReport& report,
                                                           ProcessConfig& process);
std::unique_ptr<ConfigSectionReader> makePageReader(ConfigReport& report, UserDataPage& page);

}  // namespace mtc::core
