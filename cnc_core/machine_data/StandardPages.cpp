#include "cnc_core/machine_data/StandardPages.h"

#include <string>

namespace mtc::core {
namespace {

/// Elements the operator and the programs set: writable by all, password
/// for the operator (protection "0 0 0 1" of seed 002, 5.1).
MachineDataElement limit(int number, const char* designation, MachineDataType type, double maximum,
                         double defaultValue, const char* unit) {
    MachineDataElement e;
    e.number = number;
    e.designation = designation;
    e.type = type;
    e.minimum = 0.0;
    e.maximum = maximum;
    e.defaultValue = defaultValue;
    e.unit = unit;
    e.password = true;
    return e;
}

/// Elements only the NC updates: protected for NC, SPS and GUI ("1 1 1 1").
MachineDataElement status(int number, const char* designation, MachineDataType type, double maximum,
                          const char* unit) {
    MachineDataElement e = limit(number, designation, type, maximum, 0.0, unit);
    e.protectedNc = e.protectedSps = e.protectedGui = true;
    return e;
}

MachineDataElement plain(int number, std::string designation, MachineDataType type, double minimum,
                         double maximum, double defaultValue) {
    MachineDataElement e;
    e.number = number;
    e.designation = std::move(designation);
    e.type = type;
    e.minimum = minimum;
    e.maximum = maximum;
    e.defaultValue = defaultValue;
    return e;
}

}  // namespace

MachineDataPage adaptiveFeedPage() {
    using T = MachineDataType;
    MachineDataPage page;
    page.number = kAdaptiveFeedPage;
    page.title = "Adaptive feed control";
    page.elements = {
        status(1, "Adapt. feed control active", T::Bool, 1, ""),
        limit(2, "Reference axis", T::Sint, 12, 0, ""),
        limit(3, "Amplification", T::Ampl, 100.0, 0.1, "1/s"),
        limit(4, "Measuring period idling torque", T::Uint, 65535, 200, "ms"),
        status(5, "Current idling torque", T::Perc, 999.9, "%"),
        limit(6, "Maximum idling torque", T::Perc, 999.9, 0, "%"),
        status(7, "Current machining torque", T::Perc, 999.9, "%"),
        status(8, "Peak machining torque", T::Perc, 999.9, "%"),
        limit(9, "Minimum machining torque", T::Perc, 999.9, 0, "%"),
        limit(10, "Limiting machining torque", T::Perc, 999.9, 0, "%"),
        status(11, "Current feed reduction", T::Perc, 100.0, "%"),
        status(12, "Peak feed reduction", T::Perc, 100.0, "%"),
        limit(13, "Maximum feed reduction", T::Perc, 100.0, 0, "%"),
        limit(14, "Stall torque", T::Perc, 999.9, 0, "%"),
    };
    return page;
}

MachineDataPage restartPage() {
    using T = MachineDataType;
    MachineDataPage page;
    page.number = kRestartPage;
    page.title = "NC program restart and REPOS";
    for (int spindle = 1; spindle <= 3; ++spindle)
        page.elements.push_back(plain(
            spindle, "Rotary axis mode spindle " + std::to_string(spindle), T::Bool, 0, 1, 0));
    page.elements.push_back(plain(4, "Transformation selection", T::Sint, 30, 32, 30));
    for (int spindle = 1; spindle <= 4; ++spindle)
        page.elements.push_back(plain(4 + spindle, "T no. tool spindle " + std::to_string(spindle),
                                      T::Int, 0, 9999999, 0));
    return page;
}

MachineDataPage functionBufferPage() {
    MachineDataPage page;
    page.number = kFunctionBufferPage;
    page.title = "M(16) and Q function buffers";
    page.subTitles = {"M(16) functions", "Q functions"};
    for (int element = 1; element <= 40; ++element)
        page.elements.push_back(plain(element, "Aux. Function " + std::to_string(element),
                                      MachineDataType::Int, 0, 2147483647.0, 0));
    return page;
}

MachineDataPage userPage(const UserDataPage& user) {
    MachineDataPage page;
    page.number = user.number;
    page.title = user.title;
    for (const UserDataElement& u : user.elements) {
        MachineDataElement e =
            plain(u.number, u.designation,
                  machineDataTypeFromName(u.type).value_or(MachineDataType::Real), u.minimum,
                  u.maximum, u.defaultValue);
        e.unit = u.unit;
        e.protectedNc = u.protectedNc;
        e.protectedSps = u.protectedSps;
        e.protectedGui = u.protectedGui;
        e.password = u.password;
        page.elements.push_back(e);
    }
    return page;
}

}  // namespace mtc::core
