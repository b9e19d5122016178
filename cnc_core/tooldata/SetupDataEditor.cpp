#include "cnc_core/tooldata/SetupDataEditor.h"

#include <sys/stat.h>

#include <cctype>

#include "cnc_core/program/FileText.h"

namespace mtc::core {

namespace {

/// "12" or "T12" -> 12 inside 1..high; false with a refusal into `text`.
bool numberWithLetter(DataFileText& text, char letter, const std::string& given, long long high,
                      long long& out) {
    const bool tagged = !given.empty() && std::toupper(static_cast<unsigned char>(given[0])) ==
                                              static_cast<unsigned char>(letter);
    const std::string digits = tagged ? given.substr(1) : given;
    return text.integer(0, std::string(1, letter), digits, 1, high, out);
}

std::string toolName(int tool, int edge = 0) {
    return "T" + std::to_string(tool) + (edge > 0 ? " E" + std::to_string(edge) : "");
}

/// Reads and checks the file of `what` (tools or offsets) into `read`;
/// false with the reasons in `diagnostics`.
template <typename Tables, typename Parse>
bool readTables(const std::string& path, const char* code, Parse parse, Tables& read,
                DiagnosticList& diagnostics) {
    std::string text, error;
    if (!readFileText(path, text, error)) {
        diagnostics.error(code, {}, path + ": " + error + "; the file is not overwritten");
        return false;
    }
    if (!parse(text, path, read, diagnostics)) {
        diagnostics.error(code, {}, path + " is refused (see above): it is not overwritten");
        return false;
    }
    return true;
}

}  // namespace

std::string SetupDataEdit::reason(Language language) const {
    for (const Diagnostic& d : diagnostics.items()) {
        if (d.severity != Severity::Error) continue;
        // The value checks write "<input>:0: key ..."; the rest names a file.
        Diagnostic shown = d;
        const std::size_t mark = d.message.find(":0: ");
        if (mark != std::string::npos && d.message.find(' ') > mark)
            shown.message = d.message.substr(mark + 4);
        return messageLine(shown, language);
    }
    return {};
}

std::string fileStamp(const std::string& path) {
    struct stat info {};
    if (path.empty() || ::stat(path.c_str(), &info) != 0) return "";
    return std::to_string(info.st_size) + ":" + std::to_string(info.st_mtim.tv_sec) + "." +
           std::to_string(info.st_mtim.tv_nsec) + ":" + std::to_string(info.st_ino);
}

SetupDataEditor::SetupDataEditor(SetupData& data, SetupDataFiles files, std::string inputName,
                                 double lockWaitSeconds)
    : data_(data),
      files_(std::move(files)),
      inputName_(std::move(inputName)),
      lockWait_(lockWaitSeconds),
      toolStamp_(fileStamp(files_.tools)),
      offsetStamp_(fileStamp(files_.offsets)) {}

SetupDataEdit SetupDataEditor::setToolValues(int process, int tool, int edge,
                                             const KeyValues& values) {
    return commitTools(process, [&](ToolList& list, DataFileText& text, DiagnosticList&) {
        const ToolEdge* existing = list.edge(tool, edge);
        ToolEdge changed = existing ? *existing : ToolEdge{};
        changed.edge = edge;
        std::string name;
        for (const auto& [key, value] : values)
            applyToolValue(text, 0, key, value, changed, name);
        if (text.failed()) return false;
        list.setEdge(tool, changed, name);
        return true;
    });
}

SetupDataEdit SetupDataEditor::addTool(int process, const std::string& toolText) {
    return commitTools(process, [&](ToolList& list, DataFileText& text, DiagnosticList& out) {
        long long number = 0;
        if (!numberWithLetter(text, 'T', toolText, kMaxToolNumber, number)) return false;
        if (list.find(static_cast<int>(number))) {
            out.error("TOOL_EXISTS", {},
                      toolName(static_cast<int>(number)) + " is already in the tool list");
            return false;
        }
        list.setEdge(static_cast<int>(number), ToolEdge{});
        return true;
    });
}

SetupDataEdit SetupDataEditor::addEdge(int process, int tool, const std::string& edgeText) {
    return commitTools(process, [&](ToolList& list, DataFileText& text, DiagnosticList& out) {
        long long number = 0;
        if (!numberWithLetter(text, 'E', edgeText, kMaxEdgeNumber, number)) return false;
        const int edge = static_cast<int>(number);
        if (!list.find(tool)) {
            out.error("TOOL_UNKNOWN", {}, toolName(tool) + " is not in the tool list");
            return false;
        }
        if (list.edge(tool, edge)) {
            out.error("TOOL_EXISTS", {}, toolName(tool, edge) + " is already in the tool list");
            return false;
        }
        ToolEdge added;
        added.edge = edge;
        list.setEdge(tool, added);
        return true;
    });
}

SetupDataEdit SetupDataEditor::removeTool(int process, int tool) {
    return commitTools(process, [&](ToolList& list, DataFileText&, DiagnosticList& out) {
        if (list.removeTool(tool)) return true;
        out.error(
            "TOOL_UNKNOWN", {},
            toolName(tool) + " is not in the tool list of process " + std::to_string(process));
        return false;
    });
}

SetupDataEdit SetupDataEditor::removeEdge(int process, int tool, int edge) {
    return commitTools(process, [&](ToolList& list, DataFileText&, DiagnosticList& out) {
        if (list.removeEdge(tool, edge)) return true;
        out.error("TOOL_UNKNOWN", {},
                  toolName(tool, edge) + " is not in the tool list of process " +
                      std::to_string(process));
        return false;
    });
}

SetupDataEdit SetupDataEditor::setOffsets(int process, int code, const KeyValues& values) {
    return commitOffsets(process, [&](ZeroOffsetTable& table, DataFileText& text) {
        for (const auto& [column, value] : values)
            applyOffsetValue(text, 0, code, column, value, table);
        return !text.failed();
    });
}

bool SetupDataEditor::refresh(DiagnosticList& diagnostics) {
    constexpr double kLookWait = 0.1;  // a writer holds the lock for milliseconds
    bool takenOver = false;
    for (const bool tools : {true, false}) {
        const std::string& file = tools ? files_.tools : files_.offsets;
        const std::string stamp = fileStamp(file);
        std::string& refused = tools ? refusedToolStamp_ : refusedOffsetStamp_;
        if (stamp.empty() || stamp == (tools ? toolStamp_ : offsetStamp_) || stamp == refused)
            continue;
        const FileLock lock(file, kLookWait);
        if (!lock.locked()) continue;
        SetupDataEdit look;
        if (tools ? takeOverTools(look) : takeOverOffsets(look))
            takenOver = true;
        else
            refused = stamp;  // said once; a save will not overwrite it either
        diagnostics.append(look.diagnostics);
    }
    return takenOver;
}

SetupDataEdit SetupDataEditor::commitTools(int process, const ToolChange& change) {
    SetupDataEdit edit;
    const std::shared_ptr<ToolList> list = data_.tools(process);
    if (!list) {
        edit.diagnostics.error("TOOL_UNKNOWN", {},
                               "process " + std::to_string(process) + " has no tool list");
        return edit;
    }
    // The lock first: from reading the file again to writing it, no other
    // program writes it (the same lock `md set` and the panel take).
    std::optional<FileLock> lock;
    if (!files_.tools.empty()) lock.emplace(files_.tools, lockWait_);
    const bool mayWrite = !lock || (lock->locked() && takeOverTools(edit));
    ToolList changed = *list;
    DataFileText text(inputName_, edit.diagnostics, "TOOL_VALUE");
    if (!change(changed, text, edit.diagnostics)) return edit;
    *list = std::move(changed);
    edit.changed = true;
    save(true, lock, mayWrite, edit);
    return edit;
}

SetupDataEdit SetupDataEditor::commitOffsets(int process, const OffsetChange& change) {
    SetupDataEdit edit;
    const std::shared_ptr<ZeroOffsetTable> table = data_.offsets(process);
    if (!table) {
        edit.diagnostics.error("OFFSET_VALUE", {},
                               "process " + std::to_string(process) + " has no zero offsets");
        return edit;
    }
    std::optional<FileLock> lock;
    if (!files_.offsets.empty()) lock.emplace(files_.offsets, lockWait_);
    const bool mayWrite = !lock || (lock->locked() && takeOverOffsets(edit));
    ZeroOffsetTable changed = *table;
    DataFileText text(inputName_, edit.diagnostics, "OFFSET_VALUE");
    if (!change(changed, text)) return edit;
    *table = changed;
    edit.changed = true;
    save(false, lock, mayWrite, edit);
    return edit;
}

bool SetupDataEditor::takeOverTools(SetupDataEdit& edit) {
    const std::string stamp = fileStamp(files_.tools);
    if (stamp == toolStamp_ || stamp.empty()) return true;
    ToolLists read;
    if (!readTables(files_.tools, "TOOL_FILE", parseToolFile, read, edit.diagnostics)) return false;
    for (auto& [process, list] : read) {
        if (!data_.tools(process)) {
            edit.diagnostics.error("TOOL_FILE", {},
                                   files_.tools + ": process " + std::to_string(process) +
                                       " is not in the machine configuration; not overwritten");
            return false;
        }
    }
    for (auto& [process, list] : read)
        *data_.tools(process) = std::move(list);
    edit.diagnostics.warning(
        "SETUP_DATA_TAKEN_OVER", {},
        "the tool lists another program wrote to " + files_.tools + " were taken over first");
    toolStamp_ = stamp;
    return true;
}

bool SetupDataEditor::takeOverOffsets(SetupDataEdit& edit) {
    const std::string stamp = fileStamp(files_.offsets);
    if (stamp == offsetStamp_ || stamp.empty()) return true;
    ZeroOffsetTables read;
    if (!readTables(files_.offsets, "OFFSET_FILE", parseOffsetFile, read, edit.diagnostics))
        return false;
    for (auto& [process, table] : read) {
        if (!data_.offsets(process)) {
            edit.diagnostics.error("OFFSET_FILE", {},
                                   files_.offsets + ": process " + std::to_string(process) +
                                       " is not in the machine configuration; not overwritten");
            return false;
        }
    }
    for (auto& [process, table] : read)
        *data_.offsets(process) = table;
    edit.diagnostics.warning(
        "SETUP_DATA_TAKEN_OVER", {},
        "the zero offsets another program wrote to " + files_.offsets + " were taken over first");
    offsetStamp_ = stamp;
    return true;
}

void SetupDataEditor::save(bool tools, const std::optional<FileLock>& lock, bool mayWrite,
                           SetupDataEdit& edit) {
    const std::string& file = tools ? files_.tools : files_.offsets;
    if (!lock) return;  // not kept in a file: the change holds until the program ends
    const char* code = tools ? "TOOL_FILE_LOCKED" : "OFFSET_FILE_LOCKED";
    if (!lock->locked()) {
        edit.diagnostics.error(code, {}, "the change is NOT saved: " + lock->error());
        return;
    }
    if (!mayWrite) return;  // the reason is in the diagnostics already
    edit.saved =
        tools ? data_.saveTools(file, edit.diagnostics) : data_.saveOffsets(file, edit.diagnostics);
    if (edit.saved) (tools ? toolStamp_ : offsetStamp_) = fileStamp(file);
}

}  // namespace mtc::core
