#pragma once

#include <optional>
#include <string>

#include "cli/CliOptions.h"
#include "cnc_core/tooldata/SetupData.h"

namespace mtc::cli {

/// `tools get [T<n>]` / `tools set T<n> [E<m>] KEY=VALUE... | T<n> [E<m>] delete`:
/// the tool list of --process, kept beside the machine data (docs/CLI.md).
int runToolsCommand(const CliOptions& options);

/// `offsets get [G5x]` / `offsets set G5x COLUMN=VALUE...`: the zero
/// offsets G54..G59 of --process, kept beside the machine data.
int runOffsetsCommand(const CliOptions& options);

/// The tool lists and zero offsets a run or restart works with: the machine
/// configuration's, replaced by the files beside `dataFile` (--data) when
/// one is given ("" or "-": none). False (reasons in `diagnostics`) when a
/// file is refused.
bool loadRunSetupData(const core::MachineConfig& machine, const std::string& dataFile,
                      std::optional<core::SetupData>& data, core::DiagnosticList& diagnostics);

}  // namespace mtc::cli
