#pragma once

#include <map>
#include <memory>
#include <string>

#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/tooldata/ToolListFile.h"
#include "cnc_core/tooldata/ZeroOffsetFile.h"

namespace mtc::core {

/// Where a cell's tool lists and zero offsets are kept: beside the machine
/// data file, same name with the extensions `.tools` and `.offsets`
/// (`cell.mdt` -> `cell.tools`, `cell.offsets`). Empty = not kept.
struct SetupDataFiles {
    std::string tools;
    std::string offsets;
};
SetupDataFiles setupDataFilesBeside(const std::string& machineDataFile);

/// The tool list and the zero offset table of every process of a cell:
/// first the machine configuration's (`[process N tools]`, `[process N
/// zero-offsets]`), then what the files beside the machine data hold. The
/// interpreter reads them through the shared pointers (InterpreterServices),
/// so a change is seen by the next block.
class SetupData {
  public:
    /// The configuration's content; its problems (bad zero offset columns)
    /// go to `diagnostics`.
    static SetupData fromConfig(const MachineConfig& config, DiagnosticList& diagnostics);

    /// Replaces the content of each file that exists (per process: a
    /// process without a section in the file keeps what it had). A file that is
    /// refused (syntax, range, a process the configuration does not have)
    /// changes nothing; false, with every reason in `diagnostics`.
    bool load(const SetupDataFiles& files, DiagnosticList& diagnostics);
    /// Takes the content of `other` (read for the same configuration) into
    /// the lists and tables the interpreters already read.
    void adopt(const SetupData& other);
    /// Write the tool lists / zero offsets atomically; false with a
    /// diagnostic (TOOL_FILE_SAVE / OFFSET_FILE_SAVE) when they cannot.
    bool saveTools(const std::string& file, DiagnosticList& diagnostics) const;
    bool saveOffsets(const std::string& file, DiagnosticList& diagnostics) const;

    /// The tool list / zero offsets of `process` (nullptr: no such process).
    std::shared_ptr<ToolList> tools(int process) const;
    std::shared_ptr<ZeroOffsetTable> offsets(int process) const;
    ToolLists allTools() const;
    ZeroOffsetTables allOffsets() const;

  private:
    std::map<int, std::shared_ptr<ToolList>> tools_;
    std::map<int, std::shared_ptr<ZeroOffsetTable>> offsets_;
};

}  // namespace mtc::core
