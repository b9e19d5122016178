#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/machine/ZeroOffsetTable.h"
#include "cnc_core/tooldata/DataFileText.h"

namespace mtc::core {

/// The zero offset tables of a cell by process number.
using ZeroOffsetTables = std::map<int, ZeroOffsetTable>;

/// Format name of the zero offset file (docs/TOOL-DATA.md).
inline constexpr std::string_view kOffsetFileFormat = "mtc200-offsets";

/// Largest |offset|, mm or degrees.
inline constexpr double kMaxZeroOffset = 99999.9999;

/// The file text: per process one record per code G54..G59 with every
/// column that is not 0.
std::string formatOffsetFile(const ZeroOffsetTables& tables);

/// Reads a zero offset file (records `G54 X=-150 Y=-80 Z=-120`; a column
/// not given is 0). On any problem returns false, `tables` is unchanged and
/// `diagnostics` has every refusal (code OFFSET_FILE).
bool parseOffsetFile(std::string_view text, const std::string& fileName, ZeroOffsetTables& tables,
                     DiagnosticList& diagnostics);

/// One `COLUMN=value` of code G`code` (the record syntax, also what
/// `mtc200-cli offsets set` takes) into `table`; false with a refusal.
bool applyOffsetValue(DataFileText& text, int line, int code, const std::string& column,
                      const std::string& value, ZeroOffsetTable& table);

/// The columns shown for a process (CLI, panel): every definition its axes
/// can have (docs/MACHINE-CONFIG.md), plus every column that holds a value.
std::vector<AxisDefinition> zeroOffsetColumns(const ProcessConfig& process,
                                              const ZeroOffsetTable& table);

/// "G54" -> 54 (G54..G59); 0 otherwise.
int zeroOffsetCode(std::string_view word);

}  // namespace mtc::core
