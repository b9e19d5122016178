#pragma once

#include <map>
#include <string>
#include <string_view>

#include "cnc_core/tooldata/DataFileText.h"
#include "cnc_core/tooldata/ToolList.h"

namespace mtc::core {

/// The tool lists of a cell by process number.
using ToolLists = std::map<int, ToolList>;

/// Largest tool number T and cutting edge number E (seed 001 ch. 6).
inline constexpr long long kMaxToolNumber = 9999999;
inline constexpr long long kMaxEdgeNumber = 9;

/// Format name of the tool list file (docs/TOOL-DATA.md).
inline constexpr std::string_view kToolFileFormat = "mtc200-tools";

/// The file text of `lists`: every edge of every tool as one record with
/// all its values, processes in order.
std::string formatToolFile(const ToolLists& lists);

/// Reads a tool list file. On any problem returns false, `lists` is left
/// as it was and `diagnostics` has every refusal (code TOOL_FILE) naming
/// `fileName`, line, key, value and the allowed range.
bool parseToolFile(std::string_view text, const std::string& fileName, ToolLists& lists,
                   DiagnosticList& diagnostics);

/// One edge value given as `key=value` (the record syntax, also what
/// `mtc200-cli tools set` takes): checks and stores it into `edge` or
/// `name`; false (with a refusal into `text`) when the key is unknown or
/// the value is out of its range.
bool applyToolValue(DataFileText& text, int line, const std::string& key, const std::string& value,
                    ToolEdge& edge, std::string& name);

/// The allowed range of one edge key as refusals name it ("0 .. 999.99999
/// mm", "0 .. 9"; "" for an unknown key), for prompts.
std::string toolValueRange(const std::string& key);

/// The keys of an edge record with their allowed ranges, for help texts.
const char* toolKeysHelp();

}  // namespace mtc::core
