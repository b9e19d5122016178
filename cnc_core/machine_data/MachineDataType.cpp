#include "cnc_core/machine_data/MachineDataType.h"

#include <cmath>
#include <cstdio>

#include "cnc_core/text/Numbers.h"

namespace mtc::core {

const char* machineDataTypeName(MachineDataType type) {
    switch (type) {
        case MachineDataType::Bool:
            return "BOOL";
        case MachineDataType::Sint:
            return "SINT";
        case MachineDataType::Uint:
            return "UINT";
        case MachineDataType::Ampl:
            return "AMPL";
        case MachineDataType::Perc:
            return "PERC";
        case MachineDataType::Int:
            return "INT";
        case MachineDataType::Real:
            return "REAL";
    }
    return "REAL";
}

std::optional<MachineDataType> machineDataTypeFromName(std::string_view name) {
    for (MachineDataType type :
         {MachineDataType::Bool, MachineDataType::Sint, MachineDataType::Uint,
          MachineDataType::Ampl, MachineDataType::Perc, MachineDataType::Int,
          MachineDataType::Real})
        if (name == machineDataTypeName(type)) return type;
    return std::nullopt;
}

bool machineDataTypeIsWhole(MachineDataType type) {
    return type == MachineDataType::Bool || type == MachineDataType::Sint ||
           type == MachineDataType::Uint || type == MachineDataType::Int;
}

int machineDataTypeDecimals(MachineDataType type) {
    if (machineDataTypeIsWhole(type)) return 0;
    if (type == MachineDataType::Ampl) return 2;
    if (type == MachineDataType::Perc) return 1;
    return -1;
}

std::optional<double> normalizeMachineDataValue(MachineDataType type, double value) {
    if (!std::isfinite(value)) return std::nullopt;
    const int decimals = machineDataTypeDecimals(type);
    if (decimals == 0) {
        if (value != std::floor(value)) return std::nullopt;
        return value;
    }
    if (decimals < 0) return value;
    const double scale = std::pow(10.0, decimals);
    const double rounded = std::round(value * scale) / scale;
    return rounded == 0.0 ? 0.0 : rounded;  // no "-0.0"
}

std::string formatMachineDataValue(MachineDataType type, double value) {
    const int decimals = machineDataTypeDecimals(type);
    return decimals >= 0 ? formatFixed(value, decimals) : formatGeneral(value, 10);
}

}  // namespace mtc::core
