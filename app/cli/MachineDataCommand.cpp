#include "cli/MachineDataCommand.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "cli/CliOutput.h"
#include "cli/MachineDataOutput.h"
#include "cli/MachineSetup.h"
#include "cnc_core/machine_data/MachineDataLocation.h"
#include "cnc_core/machine_data/SharedMachineDataFile.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::cli {
namespace {

using core::MachineDataStatus;

/// A whole number in `text` (all of it), or nullopt.
std::optional<int> wholeNumber(const std::string& text) {
    if (text.empty() || text.size() > 9 ||
        text.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
    return std::atoi(text.c_str());
}

/// A finite number in `text` (all of it), or nullopt.
std::optional<double> number(const std::string& text) {
    if (text.empty()) return std::nullopt;
    double value = 0.0;
    if (core::readNumberPrefix(text, value) != text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

core::MachineDataWriter writerFrom(const std::string& name) {
    if (name == "nc") return core::MachineDataWriter::Nc;
    if (name == "sps") return core::MachineDataWriter::Sps;
    return core::MachineDataWriter::Gui;
}

/// The cell, its machine data loaded from the data file, and the report.
struct Session {
    core::MachineConfig config;
    std::optional<core::MachineDataStore> store;
    std::optional<core::SharedMachineDataFile> file;
    bool mayOverwrite = true;
    bool defaultLocation = false;  ///< the file is the default one: its directory may be made
    MachineDataReport report;
};

/// Loads machine, process and data file; false (exit 2 printed) on failure.
bool open(const CliOptions& options, Session& s, int& exitCode) {
    core::DiagnosticList problems;
    std::optional<core::MachineConfig> config = loadMachine(options.machineFile, problems);
    if (!config || !checkProcessExists(*config, options.process, problems)) {
        exitCode = reportSetupFailure(problems, options.json);
        return false;
    }
    s.config = std::move(*config);
    s.store.emplace(s.config);
    s.report.process = options.process;
    s.report.processName = s.config.process(options.process)->name;
    const std::string& data = options.machineData.dataFile;
    s.defaultLocation = data.empty();
    s.report.dataFile = data == "-"    ? ""
                        : data.empty() ? core::defaultMachineDataPath(s.config.name)
                                       : data;
    if (s.report.dataFile.empty()) return true;
    s.file.emplace(s.report.dataFile);
    // `md set` is a read-modify-write: the file stays locked until it is saved
    // (its lock file lives beside it, so the default directory is made first).
    const bool set = options.arguments.size() > 0 && options.arguments[0] == "set";
    std::string ignored;  // a directory that cannot be made is reported by the save
    if (set && s.defaultLocation) core::makeParentDirectories(s.report.dataFile, ignored);
    core::MachineDataLoadResult loaded = s.file->open(*s.store, set);
    s.mayOverwrite = loaded.mayOverwrite;
    s.report.diagnostics.append(loaded.diagnostics);
    return true;
}

/// `md get [PAGE]`.
int get(const CliOptions& options, Session& s) {
    if (options.arguments.size() > 2)
        return reportUsageError("'md get' takes one PAGE", options.json);
    if (options.arguments.size() == 1) {
        if (options.machineData.sub >= 0)
            return reportUsageError("--sub needs a PAGE ('md get PAGE --sub N')", options.json);
        printPageList(*s.store, s.report, options.json);
        return 0;
    }
    const std::optional<int> page = wholeNumber(options.arguments[1]);
    if (!page)
        return reportUsageError("PAGE '" + options.arguments[1] + "' is not a page number",
                                options.json);
    const core::MachineDataPage* definition = s.store->page(options.process, *page);
    if (!definition) {
        s.report.diagnostics.error("MTD_UNKNOWN_PAGE", {},
                                   "process " + std::to_string(options.process) +
                                       " has no machine data page " + std::to_string(*page) +
                                       " ('md get' lists its pages)");
        printRefusal(s.report, options.json);
        return 1;
    }
    const int sub = options.machineData.sub;
    const std::vector<int> subs = definition->subs();
    if (sub >= 0 && std::find(subs.begin(), subs.end(), sub) == subs.end())
        return reportUsageError("page " + options.arguments[1] +
                                    (definition->subTitles.empty()
                                         ? std::string(" has no sub-pages (leave --sub out)")
                                         : " has no sub " + std::to_string(sub) + " (1.." +
                                               std::to_string(definition->subTitles.size()) + ")"),
                                options.json);
    if (options.json)
        printPageJson(*s.store, *definition, s.report, sub);
    else
        printPageText(*s.store, *definition, s.report, sub);
    return 0;
}

/// The refusal message for a write `status` of `address`.
std::string refusalText(const core::MachineDataStore& store, const core::MachineDataAddress& a,
                        MachineDataStatus status) {
    std::string text = "page " + std::to_string(a.page) + " element " + std::to_string(a.element);
    const core::MachineDataPage* page = store.page(a.process, a.page);
    const core::MachineDataElement* e = page ? page->element(a.element) : nullptr;
    if (e) text += " (" + e->designation + ")";
    text += std::string(": ") + core::machineDataStatusText(status);
    if (e && status == MachineDataStatus::OutOfRange)
        text += " " + core::formatMachineDataValue(e->type, e->minimum) + ".." +
                core::formatMachineDataValue(e->type, e->maximum) + " " + e->unit;
    double old = 0.0;
    if (e && store.read(a, old) == MachineDataStatus::Ok)
        text += "; the value stays " + core::formatMachineDataValue(e->type, old);
    return text;
}

/// Saves after a successful set; false (exit 2) when it cannot.
bool save(Session& s) {
    if (!s.file) return true;
    std::string error;
    if (!s.mayOverwrite)
        error = "the data file could not be kept aside, so it is not overwritten";
    else if (!s.defaultLocation || core::makeParentDirectories(s.report.dataFile, error)) {
        core::MachineDataSync sync = s.file->save(*s.store);
        s.report.diagnostics.append(sync.diagnostics);
        error = sync.error;
    }
    if (error.empty()) return true;
    s.report.diagnostics.error("MD_FILE_SAVE", {}, "the value was NOT saved: " + error);
    return false;
}

/// `md set PAGE ELEMENT VALUE`.
int set(const CliOptions& options, Session& s) {
    const auto& args = options.arguments;
    if (args.size() != 4)
        return reportUsageError("'md set' needs PAGE ELEMENT VALUE", options.json);
    const std::optional<int> page = wholeNumber(args[1]);
    const std::optional<int> element = wholeNumber(args[2]);
    const std::optional<double> value = number(args[3]);
    if (!page || !element)
        return reportUsageError(
            "PAGE and ELEMENT must be whole numbers, got '" + args[1] + "' '" + args[2] + "'",
            options.json);
    if (!value) return reportUsageError("VALUE '" + args[3] + "' is not a number", options.json);
    const core::MachineDataPage* definition = s.store->page(options.process, *page);
    int sub = options.machineData.sub;
    if (definition && sub < 0 && definition->subTitles.size() > 0)
        return reportUsageError("page " + args[1] + " needs --sub N (1.." +
                                    std::to_string(definition->subTitles.size()) + ")",
                                options.json);
    const core::MachineDataAddress address{*page, options.process, sub < 0 ? 0 : sub, *element};
    const core::MachineDataElement* shown = definition ? definition->element(*element) : nullptr;
    double before = 0.0;
    // The store names the reason for an address it does not hold (page,
    // process or element); one its page table does not describe is refused too.
    MachineDataStatus status = s.store->read(address, before);
    if (status == MachineDataStatus::Ok && !shown) status = MachineDataStatus::UnknownElement;
    if (status == MachineDataStatus::Ok)
        status = s.store->write(address, *value, writerFrom(options.machineData.writer),
                                options.machineData.password);
    if (status != MachineDataStatus::Ok) {
        s.report.diagnostics.error(core::machineDataStatusCode(status), {},
                                   refusalText(*s.store, address, status));
        printRefusal(s.report, options.json);
        return 1;
    }
    if (!save(s)) {
        printRefusal(s.report, options.json);
        return 2;
    }
    double after = 0.0;
    s.store->read(address, after);
    printSetResult(address, *shown, before, after, s.report, options.json);
    return 0;
}

}  // namespace

int runMachineDataCommand(const CliOptions& options) {
    const std::string action = options.arguments.empty() ? "" : options.arguments[0];
    if (action != "get" && action != "set")
        return reportUsageError("'md' needs 'get [PAGE]' or 'set PAGE ELEMENT VALUE'",
                                options.json);
    if (action == "get" &&
        (options.machineData.writer != "gui" || !options.machineData.password.empty()))
        return reportUsageError("--as and --password belong to 'md set'", options.json);
    Session session;
    int exitCode = 0;
    if (!open(options, session, exitCode)) return exitCode;
    if (!session.mayOverwrite && action == "set") {
        printRefusal(session.report, options.json);
        return 2;
    }
    return action == "get" ? get(options, session) : set(options, session);
}

}  // namespace mtc::cli
