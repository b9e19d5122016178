#include "cli/SetupDataCommand.h"

#include <cstdio>
#include <optional>

#include "cli/CliOutput.h"
#include "cli/MachineSetup.h"
#include "cnc_core/machine_data/MachineDataLocation.h"
#include "cnc_core/tooldata/SetupData.h"
#include "cnc_core/tooldata/SetupDataEditor.h"

namespace mtc::cli {

namespace {

/// The cell, its tool and offset data loaded from the files, and where they go.
struct Session {
    core::MachineConfig config;
    std::optional<core::SetupData> data;
    core::SetupDataFiles files;
    bool defaultLocation = false;
    core::DiagnosticList diagnostics;
    std::optional<core::SetupDataEditor> editor;
};

/// Loads machine, process and the data files; false (exit code set) on failure.
bool open(const CliOptions& options, Session& s, int& exitCode) {
    core::DiagnosticList problems;
    std::optional<core::MachineConfig> config = loadMachine(options.machineFile, problems);
    if (!config || !checkProcessExists(*config, options.process, problems)) {
        exitCode = reportSetupFailure(problems, options.json);
        return false;
    }
    s.config = std::move(*config);
    s.data.emplace(core::SetupData::fromConfig(s.config, problems));
    const std::string& data = options.machineData.dataFile;
    s.defaultLocation = data.empty();
    s.files = core::setupDataFilesBeside(data.empty() ? core::defaultMachineDataPath(s.config.name)
                                                      : data);
    // Before the files are read: a change another program makes from now on
    // is taken over when this one saves.
    s.editor.emplace(*s.data, s.files, "command line");
    if (!s.data->load(s.files, problems) || problems.hasErrors()) {
        exitCode = reportSetupFailure(problems, options.json);
        return false;
    }
    return true;
}

/// Before a change goes through the editor (checks, lock, atomic save): the
/// default location's folder is made; without a file a warning says the
/// change is not kept. False (diagnostic) when the folder cannot be made.
bool prepareSave(Session& s, bool tools) {
    const std::string& file = tools ? s.files.tools : s.files.offsets;
    std::string error;
    if (!file.empty() && s.defaultLocation && !core::makeParentDirectories(file, error)) {
        s.diagnostics.error(tools ? "TOOL_FILE_SAVE" : "OFFSET_FILE_SAVE", {}, file + ": " + error);
        return false;
    }
    if (file.empty())
        s.diagnostics.warning("SETUP_DATA_NOT_KEPT", {},
                              "--data - keeps nothing: the change is not saved");
    return true;
}

/// Exit code of a change: 0 done (and saved where kept), 1 refused, 2 not saved.
int editOutcome(Session& s, const core::SetupDataEdit& edit, bool tools) {
    s.diagnostics.append(edit.diagnostics);
    const std::string& file = tools ? s.files.tools : s.files.offsets;
    if (!edit.changed) return 1;
    return edit.saved || file.empty() ? 0 : 2;
}

// ------------------------------------------------------------------ tools

void writeEdgeJson(JsonWriter& json, const core::ToolEdge& e) {
    json.beginObject();
    json.field("e", e.edge);
    json.field("radius", e.radius);
    json.field("radius_wear", e.radiusWear);
    json.field("l1", e.length1);
    json.field("l2", e.length2);
    json.field("l3", e.length3);
    json.field("l1_wear", e.length1Wear);
    json.field("l2_wear", e.length2Wear);
    json.field("l3_wear", e.length3Wear);
    json.field("orientation", e.orientation);
    json.field("corner_angle", e.cornerAngle);
    json.field("setting_angle", e.settingAngle);
    json.endObject();
}

void printTools(const Session& s, int process, const std::vector<const core::Tool*>& tools,
                bool asJson) {
    if (asJson) {
        JsonWriter json(stdout);
        beginStatusDocument(json, s.diagnostics.hasErrors() ? "error" : "ok");
        json.field("process", process);
        json.field("file", s.files.tools);
        json.key("tools");
        json.beginArray();
        for (const core::Tool* tool : tools) {
            json.beginObject();
            json.field("t", tool->number);
            json.field("name", tool->name);
            json.key("edges");
            json.beginArray();
            for (const core::ToolEdge& e : tool->edges)
                writeEdgeJson(json, e);
            json.endArray();
            json.endObject();
        }
        json.endArray();
        endDocumentWithDiagnostics(json, s.diagnostics);
        return;
    }
    printDiagnosticsText(stderr, s.diagnostics);
    std::printf("tools of process %d (%s)\n", process,
                s.files.tools.empty() ? "not kept" : s.files.tools.c_str());
    std::printf("%-9s %-3s %10s %9s %10s %10s %10s %3s %7s %7s  %s\n", "T", "E", "radius", "wear",
                "L1", "L2", "L3", "pos", "corner", "setting", "name");
    for (const core::Tool* tool : tools)
        for (const core::ToolEdge& e : tool->edges)
            std::printf("T%-8d E%-2d %10.5f %9.5f %10.4f %10.4f %10.4f %3d %7.2f %7.2f  %s\n",
                        tool->number, e.edge, e.radius, e.radiusWear, e.totalLength(1),
                        e.totalLength(2), e.totalLength(3), e.orientation, e.cornerAngle,
                        e.settingAngle, tool->name.c_str());
}

/// "T12" / "E3" with the ranges of the file format; false with a usage error printed.
bool tag(const std::string& word, char letter, long long high, long long& out, int& exitCode,
         bool asJson) {
    core::DiagnosticList problems;
    core::DataFileText text("command line", problems, "CLI_USAGE");
    if (word.size() >= 2 && word[0] == letter &&
        text.integer(0, std::string(1, letter), word.substr(1), 1, high, out))
        return true;
    exitCode = reportUsageError(
        problems.empty() ? "expected " + std::string(1, letter) + "<number>, got '" + word + "'"
                         : problems.items().front().message,
        asJson);
    return false;
}

int toolsGet(const CliOptions& options, Session& s) {
    const core::ToolList& list = *s.data->tools(options.process);
    std::vector<const core::Tool*> tools;
    if (options.arguments.size() > 2)
        return reportUsageError("'tools get' takes at most one T<number>", options.json);
    if (options.arguments.size() == 2) {
        long long t = 0;
        int exitCode = 2;
        if (!tag(options.arguments[1], 'T', core::kMaxToolNumber, t, exitCode, options.json))
            return exitCode;
        const core::Tool* tool = list.find(static_cast<int>(t));
        if (!tool) {
            s.diagnostics.error("TOOL_UNKNOWN", {},
                                "T" + std::to_string(t) + " is not in the tool list of process " +
                                    std::to_string(options.process));
            printTools(s, options.process, tools, options.json);
            if (!options.json) printRefusedDiagnostics(s.diagnostics);
            return 1;
        }
        tools.push_back(tool);
    } else {
        for (const core::Tool& tool : list.tools())
            tools.push_back(&tool);
    }
    printTools(s, options.process, tools, options.json);
    return 0;
}

int toolsSet(const CliOptions& options, Session& s) {
    const auto& args = options.arguments;
    if (args.size() < 3)
        return reportUsageError(
            "'tools set' needs T<n> [E<m>] KEY=VALUE... (or T<n> [E<m>] delete)", options.json);
    long long t = 0, e = 1;
    int exitCode = 2;
    if (!tag(args[1], 'T', core::kMaxToolNumber, t, exitCode, options.json)) return exitCode;
    std::size_t next = 2;
    const bool edgeGiven = args[2].size() >= 2 && args[2][0] == 'E';
    if (edgeGiven && !tag(args[2], 'E', core::kMaxEdgeNumber, e, exitCode, options.json))
        return exitCode;
    if (edgeGiven) ++next;
    const int number = static_cast<int>(t), edgeNumber = static_cast<int>(e);
    core::SetupDataEditor::KeyValues values;
    const bool remove = next + 1 == args.size() && args[next] == "delete";
    for (std::size_t i = next; i < args.size() && !remove; ++i) {
        const std::size_t eq = args[i].find('=');
        if (eq == std::string::npos)
            return reportUsageError(
                "expected KEY=VALUE, got '" + args[i] + "'; keys: " + core::toolKeysHelp(),
                options.json);
        values.emplace_back(args[i].substr(0, eq), args[i].substr(eq + 1));
    }
    int result = 2;
    if (prepareSave(s, true)) {
        const core::SetupDataEdit edit =
            !remove     ? s.editor->setToolValues(options.process, number, edgeNumber, values)
            : edgeGiven ? s.editor->removeEdge(options.process, number, edgeNumber)
                        : s.editor->removeTool(options.process, number);
        result = editOutcome(s, edit, true);
    }
    if (result != 0) {  // refused: nothing changed; 2: not saved
        printTools(s, options.process, {}, options.json);
        if (!options.json) printRefusedDiagnostics(s.diagnostics);
        return result;
    }
    const core::ToolList& list = *s.data->tools(options.process);
    std::vector<const core::Tool*> shown;
    if (const core::Tool* tool = list.find(number)) shown.push_back(tool);
    printTools(s, options.process, shown, options.json);
    return 0;
}

// ---------------------------------------------------------------- offsets

void printOffsets(const Session& s, int process, const std::vector<int>& codes, bool asJson) {
    const core::ZeroOffsetTable& table = *s.data->offsets(process);
    const std::vector<core::AxisDefinition> columns =
        core::zeroOffsetColumns(*s.config.process(process), table);
    if (asJson) {
        JsonWriter json(stdout);
        beginStatusDocument(json, s.diagnostics.hasErrors() ? "error" : "ok");
        json.field("process", process);
        json.field("file", s.files.offsets);
        json.key("offsets");
        json.beginObject();
        for (int code : codes) {
            json.key("G" + std::to_string(code));
            json.beginObject();
            for (core::AxisDefinition d : columns)
                json.field(std::string(1, core::definitionLetter(d)), table.value(code, d));
            json.endObject();
        }
        json.endObject();
        endDocumentWithDiagnostics(json, s.diagnostics);
        return;
    }
    printDiagnosticsText(stderr, s.diagnostics);
    std::printf("zero offsets of process %d (%s)\n", process,
                s.files.offsets.empty() ? "not kept" : s.files.offsets.c_str());
    std::printf("    ");
    for (core::AxisDefinition d : columns)
        std::printf(" %12c", core::definitionLetter(d));
    std::printf("\n");
    for (int code : codes) {
        std::printf("G%d", code);
        for (core::AxisDefinition d : columns)
            std::printf(" %12.4f", table.value(code, d));
        std::printf("\n");
    }
}

int offsetsGet(const CliOptions& options, Session& s) {
    if (options.arguments.size() > 2)
        return reportUsageError("'offsets get' takes at most one G54..G59", options.json);
    std::vector<int> codes;
    if (options.arguments.size() == 2) {
        const int code = core::zeroOffsetCode(options.arguments[1]);
        if (code == 0)
            return reportUsageError("expected G54..G59, got '" + options.arguments[1] + "'",
                                    options.json);
        codes.push_back(code);
    } else {
        for (int code = 54; code <= 59; ++code)
            codes.push_back(code);
    }
    printOffsets(s, options.process, codes, options.json);
    return 0;
}

int offsetsSet(const CliOptions& options, Session& s) {
    const auto& args = options.arguments;
    const int code = args.size() >= 2 ? core::zeroOffsetCode(args[1]) : 0;
    if (args.size() < 3 || code == 0)
        return reportUsageError(
            "'offsets set' needs G54..G59 COLUMN=VALUE... (columns X Y Z U V W "
            "A B C)",
            options.json);
    core::SetupDataEditor::KeyValues values;
    for (std::size_t i = 2; i < args.size(); ++i) {
        const std::size_t eq = args[i].find('=');
        if (eq == std::string::npos)
            return reportUsageError("expected COLUMN=VALUE, got '" + args[i] + "'", options.json);
        values.emplace_back(args[i].substr(0, eq), args[i].substr(eq + 1));
    }
    int result = 2;
    if (prepareSave(s, false))
        result = editOutcome(s, s.editor->setOffsets(options.process, code, values), false);
    if (result != 0) {
        printOffsets(s, options.process, {}, options.json);
        if (!options.json) printRefusedDiagnostics(s.diagnostics);
        return result;
    }
    printOffsets(s, options.process, {code}, options.json);
    return 0;
}

int dispatch(const CliOptions& options, const char* what, int (*get)(const CliOptions&, Session&),
             int (*set)(const CliOptions&, Session&)) {
    const std::string action = options.arguments.empty() ? "" : options.arguments[0];
    if (action != "get" && action != "set")
        return reportUsageError(std::string("'") + what + "' needs 'get' or 'set'", options.json);
    if (options.machineData.writer != "gui" || !options.machineData.password.empty() ||
        options.machineData.sub >= 0)
        return reportUsageError(
            std::string("--as, --password and --sub belong to 'md', not '") + what + "'",
            options.json);
    Session session;
    int exitCode = 0;
    if (!open(options, session, exitCode)) return exitCode;
    return action == "get" ? get(options, session) : set(options, session);
}

}  // namespace

bool loadRunSetupData(const core::MachineConfig& machine, const std::string& dataFile,
                      std::optional<core::SetupData>& data, core::DiagnosticList& diagnostics) {
    data.emplace(core::SetupData::fromConfig(machine, diagnostics));
    return data->load(core::setupDataFilesBeside(dataFile), diagnostics);
}

int runToolsCommand(const CliOptions& options) {
    return dispatch(options, "tools", toolsGet, toolsSet);
}

int runOffsetsCommand(const CliOptions& options) {
    return dispatch(options, "offsets", offsetsGet, offsetsSet);
}

}  // namespace mtc::cli
