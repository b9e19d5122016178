#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mtc::core {

/// What an axis physically is.
enum class AxisKind { Linear, Rotary, Spindle };

/// One axis or spindle of a process (axis parameters C...).
struct AxisConfig {
    std::string name;  ///< axis designation 1, e.g. "X", "Z2", "S1"
    AxisKind kind = AxisKind::Linear;
    std::vector<std::string> definitions;  ///< Cxx.053: first = base, rest = G20 alternates
    std::string designation2;              ///< Cxx.075, used while G31/G32 is active ("" = none)
    int polarDirection = 0;                ///< Cxx.076 (0/1)
    double minPosition = 0.0;              ///< travel limits; both 0 = endless (rotary)
    double maxPosition = 0.0;
    double maxVelocity = 10000.0;     ///< mm/min (deg/min for rotary)
    double maxAcceleration = 2000.0;  ///< mm/s^2 (deg/s^2 for rotary)
    // Spindles only:
    int spindleIndex = 0;        ///< 1..3 for S1..S3
    std::string rotaryAxisName;  ///< name in rotary axis mode, e.g. "C"
    double maxSpeed = 0.0;       ///< rpm
    int line = 0;  ///< line of its section header in the configuration file (0 = not from a file)
};

/// An M function group: the last output value is kept in M(number).
struct MGroupConfig {
    int number = 0;  ///< 1..15; group 16 is implicit ("every other M")
    std::string name;
    std::vector<int> functions;
    int resetValue = -1;  ///< value at power-on / program end / control reset
};

/// Tool data of the current tools list.
struct ToolConfig {
    int number = 0;
    double radius = 0.0;
    double length = 0.0;
    int edgeOrientation = 0;  ///< turning tools: cutting edge position 0..9
    std::string name;
};

/// Zero offset G54..G59 (and G52 base) per axis designation.
struct ZeroOffset {
    std::string code;  ///< "G54"
    std::map<std::string, double> values;
    int line = 0;  ///< line in the configuration file (0 = not from a file)
};

/// One element of a user machine data page (e.g. page 180 of the demo lathe).
struct UserDataElement {
    int number = 0;
    std::string designation;
    std::string type = "INT";  ///< BOOL SINT UINT AMPL PERC INT REAL
    double minimum = 0.0;
    double maximum = 0.0;
    double defaultValue = 0.0;
    std::string unit;
    bool protectedNc = false;   ///< NC programs (MTD(...)=...) may not write it
    bool protectedSps = false;  ///< the SPS (MTD_WR) may not write it
    bool protectedGui = false;  ///< the operator may not change it
    bool password = false;      ///< the operator needs the machine data password
};

struct UserDataPage {
    int number = 0;
    std::string title;
    std::vector<UserDataElement> elements;
};

/// One process (station) of the cell.
struct ProcessConfig {
    int index = 0;
    int line = 0;  ///< line of its [process N] header (0 = not from a file)
    std::string name;
    std::vector<AxisConfig> axes;       ///< in machine order
    std::vector<MGroupConfig> mGroups;  ///< groups 1..15 that exist
    std::vector<ToolConfig> tools;      ///< current tools list
    std::vector<ZeroOffset> zeroOffsets;
    std::vector<UserDataPage> userPages;
    /// Process parameters by number, e.g. "B004" -> "17", "B058" -> "yes".
    std::map<std::string, std::string> parameters;
    /// `[process N torque-model]` constants of the simulated reference axis
    /// of adaptive feed control ("cutting" -> 60, ...); absent keys = defaults.
    std::map<std::string, double> torqueModel;
    int toolPlaces = 0;                    ///< magazine / turret places
    std::string toolStorage = "magazine";  ///< "magazine" or "turret"
    /// `stock = ...`: the raw part the toolpath view draws (toolpath/Stock.h); "" = none.
    std::string stock;

    const AxisConfig* axis(const std::string& name) const;
    const ToolConfig* tool(int number) const;
    const MGroupConfig* mGroupOf(int mFunction) const;  ///< nullptr = group 16
    /// Yes/No parameter; `fallback` when absent or not a yes/no value.
    bool flag(const std::string& number, bool fallback = false) const;
    /// Numeric parameter; `fallback` when absent or not numeric.
    double number(const std::string& number, double fallback = 0.0) const;
    int defaultPlane() const { return static_cast<int>(number("B004", 17)); }
};

/// Reads a Yes/No process parameter: yes/no, 1/0 or true/false (any case).
/// False for anything else ("maybe"), `value` untouched.
bool parseYesNo(const std::string& text, bool& value);

/// The whole cell: the machine configuration the simulator runs on.
struct MachineConfig {
    std::string name;
    /// Password the operator gives for password-protected machine data
    /// (`[cell] md_password`); empty = the built-in default of
    /// docs/decisions/machine-data.md.
    std::string machineDataPassword;
    std::vector<ProcessConfig> processes;

    const ProcessConfig* process(int index) const;
};

}  // namespace mtc::core
