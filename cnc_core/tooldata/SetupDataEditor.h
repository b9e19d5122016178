#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cnc_core/program/FileLock.h"
#include "cnc_core/text/Messages.h"
#include "cnc_core/tooldata/SetupData.h"

namespace mtc::core {

/// What one change of the tool or zero offset data did.
struct SetupDataEdit {
    /// The data was changed: the interpreters use it from their next block.
    bool changed = false;
    /// The change is in its file (false when refused, when it could not be
    /// written, or when the data is not kept in a file at all).
    bool saved = false;
    /// Why a change was refused (TOOL_VALUE, TOOL_UNKNOWN, TOOL_EXISTS,
    /// OFFSET_VALUE) or not saved (TOOL_FILE_LOCKED, TOOL_FILE,
    /// TOOL_FILE_SAVE and the OFFSET_ ones), and notes (SETUP_DATA_TAKEN_OVER).
    DiagnosticList diagnostics;

    /// The first error's message without the "<input>:0: " prefix of the
    /// value checks ("key 'radius' = '-1': out of range (...)"), "" when none.
    /// German: the code's brief message before it (messageLine(), D-024).
    std::string reason(Language language = Language::English) const;
};

/// Every operator change of the tool lists and zero offsets, from the panel
/// and from `mtc200-cli tools|offsets set`: the values are checked by the
/// rules the files are read with (applyToolValue, applyOffsetValue: one rule
/// in one place), a refused change changes nothing, and an accepted one is
/// written at once to the file beside the machine data (SetupDataFiles),
/// atomically and one writer at a time: under the file's FileLock (the
/// lock the machine data file uses, bounded wait) the file is read again
/// and, when another program changed it since this editor last read or
/// wrote it, its processes are taken over before the change is applied and
/// written (docs/decisions/tool-data.md TOOL-006).
class SetupDataEditor {
  public:
    using KeyValues = std::vector<std::pair<std::string, std::string>>;

    /// `data` as loaded from `files` (empty names: nothing is kept);
    /// `inputName` opens the refusal messages ("command line", "entry").
    SetupDataEditor(SetupData& data, SetupDataFiles files, std::string inputName = "entry",
                    double lockWaitSeconds = FileLock::kDefaultWaitSeconds);

    const SetupDataFiles& files() const { return files_; }

    /// KEY=VALUE pairs (the tool file's keys) on edge `edge` of tool `tool`,
    /// all or none; the edge (and the tool) is made when it is not there.
    SetupDataEdit setToolValues(int process, int tool, int edge, const KeyValues& values);
    /// A new tool: `toolText` is its number ("12" or "T12", 1..9999999),
    /// made with edge E1, every value 0. Refused when it exists.
    SetupDataEdit addTool(int process, const std::string& toolText);
    /// A new edge `edgeText` ("2" or "E2", 1..9) of an existing tool, every
    /// value 0. Refused when it exists.
    SetupDataEdit addEdge(int process, int tool, const std::string& edgeText);
    /// Removes a whole tool, or one edge (the last edge removes the tool).
    SetupDataEdit removeTool(int process, int tool);
    SetupDataEdit removeEdge(int process, int tool, int edge);
    /// COLUMN=VALUE pairs of zero offset G`code` (54..59), all or none.
    SetupDataEdit setOffsets(int process, int code, const KeyValues& values);

    /// Takes over what another program saved to the files since this
    /// editor last read or wrote them (one stat per file when nothing
    /// changed; a file being written is looked at next time). True when
    /// something was taken over (a SETUP_DATA_TAKEN_OVER note in
    /// `diagnostics`); a refused file is reported once and left alone.
    bool refresh(DiagnosticList& diagnostics);

  private:
    using ToolChange = std::function<bool(ToolList&, DataFileText&, DiagnosticList&)>;
    using OffsetChange = std::function<bool(ZeroOffsetTable&, DataFileText&)>;

    SetupDataEdit commitTools(int process, const ToolChange& change);
    SetupDataEdit commitOffsets(int process, const OffsetChange& change);
    /// Under the lock: takes over the file's content when another program
    /// wrote it since this editor's last look; false (diagnostic) when the
    /// file cannot be read or is refused: then it is not overwritten.
    bool takeOverTools(SetupDataEdit& edit);
    bool takeOverOffsets(SetupDataEdit& edit);
    /// Writes the file of the tools (or offsets) under the held lock.
    void save(bool tools, const std::optional<FileLock>& lock, bool mayWrite, SetupDataEdit& edit);

    SetupData& data_;
    SetupDataFiles files_;
    std::string inputName_;
    double lockWait_;
    std::string toolStamp_;         ///< "size:mtime:inode" of the tool file at the last read/write
    std::string offsetStamp_;       ///< the same of the offset file
    std::string refusedToolStamp_;  ///< a refused tool file refresh() reported
    std::string refusedOffsetStamp_;  ///< the same of the offset file
};

/// "size:mtime:inode" of a file, "" when it is missing.
std::string fileStamp(const std::string& path);

}  // namespace mtc::core
