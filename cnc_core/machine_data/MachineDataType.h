#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace mtc::core {

/// Data types of MTC200 machine data elements (seed 002, 5.1; MACHINE-CONFIG.md).
enum class MachineDataType {
    Bool,  ///< 0 / 1
    Sint,  ///< whole number, 8 bit signed
    Uint,  ///< whole number, 16 bit unsigned
    Ampl,  ///< amplification, two decimals
    Perc,  ///< percentage, one decimal
    Int,   ///< whole number, 32 bit signed
    Real,  ///< any finite number
};

/// "BOOL", "SINT", ... for a type.
const char* machineDataTypeName(MachineDataType type);
/// The type named `name` (upper case as in the seeds); nullopt when unknown.
std::optional<MachineDataType> machineDataTypeFromName(std::string_view name);
/// True for BOOL, SINT, UINT and INT: the element takes whole numbers only.
bool machineDataTypeIsWhole(MachineDataType type);
/// Decimals shown and stored: 0 for whole types, 2 for AMPL, 1 for PERC, -1 for REAL (as is).
int machineDataTypeDecimals(MachineDataType type);
/// `value` as the element stores it: rounded to the type's decimals (AMPL, PERC);
/// nullopt when it is not finite or not a whole number for a whole type.
std::optional<double> normalizeMachineDataValue(MachineDataType type, double value);
/// The value formatted with the type's decimals ("12.5", "0.10", "30").
std::string formatMachineDataValue(MachineDataType type, double value);

}  // namespace mtc::core
