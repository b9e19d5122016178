#include "cnc_core/tooldata/SetupData.h"

#include <sys/stat.h>

#include "cnc_core/program/AtomicWrite.h"
#include "cnc_core/program/FileText.h"

namespace mtc::core {

namespace {

bool exists(const std::string& path) {
    struct stat info {};
    return !path.empty() && ::lstat(path.c_str(), &info) == 0;
}

/// Reads `path`; false with a diagnostic `code` when it cannot.
bool readData(const std::string& path, const char* code, std::string& text,
              DiagnosticList& diagnostics) {
    std::string error;
    if (readFileText(path, text, error)) return true;
    diagnostics.error(code, {}, path + ": " + error);
    return false;
}

/// Every process of `read` must exist in `known`.
template <typename Map, typename Known>
bool processesKnown(const Map& read, const Known& known, const std::string& file, const char* code,
                    DiagnosticList& diagnostics) {
    bool ok = true;
    for (const auto& entry : read)
        if (known.find(entry.first) == known.end()) {
            diagnostics.error(code, {},
                              file + ": process " + std::to_string(entry.first) +
                                  " is not in the machine configuration");
            ok = false;
        }
    return ok;
}

}  // namespace

SetupDataFiles setupDataFilesBeside(const std::string& machineDataFile) {
    SetupDataFiles files;
    if (machineDataFile.empty() || machineDataFile == "-") return files;
    std::string stem = machineDataFile;
    const std::size_t slash = stem.find_last_of('/');
    const std::size_t dot = stem.find_last_of('.');
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash + 1))
        stem.erase(dot);
    files.tools = stem + ".tools";
    files.offsets = stem + ".offsets";
    return files;
}

SetupData SetupData::fromConfig(const MachineConfig& config, DiagnosticList& diagnostics) {
    SetupData data;
    for (const ProcessConfig& process : config.processes) {
        data.tools_[process.index] = std::make_shared<ToolList>(ToolList::fromConfig(process));
        data.offsets_[process.index] =
            std::make_shared<ZeroOffsetTable>(ZeroOffsetTable::build(process, diagnostics));
    }
    return data;
}

bool SetupData::load(const SetupDataFiles& files, DiagnosticList& diagnostics) {
    bool ok = true;
    std::string text;
    if (exists(files.tools) && readData(files.tools, "TOOL_FILE", text, diagnostics)) {
        ToolLists lists;
        if (parseToolFile(text, files.tools, lists, diagnostics) &&
            processesKnown(lists, tools_, files.tools, "TOOL_FILE", diagnostics)) {
            for (auto& [process, list] : tools_)
                if (lists.count(process)) *list = lists[process];
        } else {
            ok = false;
        }
    } else if (exists(files.tools)) {
        ok = false;
    }
    if (exists(files.offsets) && readData(files.offsets, "OFFSET_FILE", text, diagnostics)) {
        ZeroOffsetTables tables;
        if (parseOffsetFile(text, files.offsets, tables, diagnostics) &&
            processesKnown(tables, offsets_, files.offsets, "OFFSET_FILE", diagnostics)) {
            for (auto& [process, table] : offsets_)
                if (tables.count(process)) *table = tables[process];
        } else {
            ok = false;
        }
    } else if (exists(files.offsets)) {
        ok = false;
    }
    return ok;
}

void SetupData::adopt(const SetupData& other) {
    for (auto& [process, list] : tools_)
        if (auto it = other.tools_.find(process); it != other.tools_.end() && it->second)
            *list = *it->second;
    for (auto& [process, table] : offsets_)
        if (auto it = other.offsets_.find(process); it != other.offsets_.end() && it->second)
            *table = *it->second;
}

bool SetupData::saveTools(const std::string& file, DiagnosticList& diagnostics) const {
    std::string error;
    if (writeFileAtomically(file, formatToolFile(allTools()), error)) return true;
    diagnostics.error("TOOL_FILE_SAVE", {}, file + ": " + error);
    return false;
}

bool SetupData::saveOffsets(const std::string& file, DiagnosticList& diagnostics) const {
    std::string error;
    if (writeFileAtomically(file, formatOffsetFile(allOffsets()), error)) return true;
    diagnostics.error("OFFSET_FILE_SAVE", {}, file + ": " + error);
    return false;
}

std::shared_ptr<ToolList> SetupData::tools(int process) const {
    auto it = tools_.find(process);
    return it == tools_.end() ? nullptr : it->second;
}

std::shared_ptr<ZeroOffsetTable> SetupData::offsets(int process) const {
    auto it = offsets_.find(process);
    return it == offsets_.end() ? nullptr : it->second;
}

ToolLists SetupData::allTools() const {
    ToolLists lists;
    for (const auto& [process, list] : tools_)
        lists[process] = *list;
    return lists;
}

ZeroOffsetTables SetupData::allOffsets() const {
    ZeroOffsetTables tables;
    for (const auto& [process, table] : offsets_)
        tables[process] = *table;
    return tables;
}

}  // namespace mtc::core
