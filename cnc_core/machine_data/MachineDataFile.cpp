#include "cnc_core/machine_data/MachineDataFile.h"

#include <sys/stat.h>

#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <locale>
#include <sstream>

#include "cnc_core/program/AtomicWrite.h"
#include "cnc_core/program/FileText.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {
namespace {

constexpr const char* kHeader = "MTC200-MACHINE-DATA 1";
constexpr std::size_t kMaxFileSize = 64u << 20;  // far above any cell; refuses absurd input

std::uint64_t fnv1a(const std::string& text, std::size_t length) {
    std::uint64_t hash = 1469598103934665603ull;
    for (std::size_t i = 0; i < length; ++i) {
        hash ^= static_cast<unsigned char>(text[i]);
        hash *= 1099511628211ull;
    }
    return hash;
}

bool fileExists(const std::string& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0;
}

/// Removes "<path>.tmpXXXXXX" files (writeFileAtomically's temporaries) that
/// a save killed before its rename left behind; one warning per file.
void removeStaleTemporaries(const std::string& path, DiagnosticList& diagnostics) {
    const std::size_t slash = path.find_last_of('/');
    const std::string directory = slash == std::string::npos ? "."
                                  : slash == 0               ? "/"
                                                             : path.substr(0, slash);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    for (const std::string& removed : core::removeStaleTemporaries(
             directory, [&](std::string_view base) { return base == name; }))
        diagnostics.warning("MD_STALE_TEMPORARY", {},
                            "removed " + removed +
                                ", the unfinished temporary file of an interrupted save (" + path +
                                " itself was not affected)");
}

/// "<path>.damaged-20240501-101500" (with "-2", "-3", ... when taken).
std::string asideName(const std::string& path) {
    char stamp[32];
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    const std::string base = path + ".damaged-" + stamp;
    std::string name = base;
    for (int n = 2; fileExists(name) && n < 1000; ++n)
        name = base + "-" + std::to_string(n);
    return name;
}

/// One "<process> <page> <sub> <element> <value>" line.
bool parseEntry(const std::string& line, MachineDataStore::Entry& entry) {
    std::istringstream in(line);
    in.imbue(std::locale::classic());  // the file's numbers whatever the desk's locale
    MachineDataAddress& a = entry.address;
    std::string extra;
    if (!(in >> a.process >> a.page >> a.sub >> a.element >> entry.value)) return false;
    return !(in >> extra);
}

std::string describe(const MachineDataStore::Entry& entry) {
    char text[128];
    std::snprintf(text, sizeof text,
                  "process %d page %d sub %d element %d = ", entry.address.process,
                  entry.address.page, entry.address.sub, entry.address.element);
    return text + formatGeneral(entry.value, 10);
}

}  // namespace

std::string MachineDataFile::serialize(const MachineDataStore& store) {
    std::string text = std::string(kHeader) + "\ncell " + store.cellName() + "\n";
    const std::vector<MachineDataStore::Entry> entries = store.entries();
    char line[160];
    for (const MachineDataStore::Entry& e : entries) {
        std::snprintf(line, sizeof line, "%d %d %d %d ", e.address.process, e.address.page,
                      e.address.sub, e.address.element);
        text += line + formatGeneral(e.value, 17) + "\n";
    }
    std::snprintf(line, sizeof line, "end %zu %016" PRIx64 "\n", entries.size(),
                  fnv1a(text, text.size()));
    return text + line;
}

bool MachineDataFile::parse(const std::string& text, std::string& cell,
                            std::vector<MachineDataStore::Entry>& entries, std::string& reason) {
    entries.clear();
    const std::size_t endLine = text.rfind("\nend ");
    if (text.compare(0, std::strlen(kHeader) + 1, std::string(kHeader) + "\n") != 0)
        return reason = "not a machine data file (header missing)", false;
    if (endLine == std::string::npos || text.back() != '\n')
        return reason = "truncated (the end line is missing)", false;
    std::size_t count = 0;
    char checksum[17] = {};
    char after = 0;
    const std::string last = text.substr(endLine + 1);
    if (std::sscanf(last.c_str(), "end %19zu %16[0-9a-f]%c", &count, checksum, &after) != 3 ||
        after != '\n' || last.size() != 4 + std::to_string(count).size() + 1 + 16 + 1)
        return reason = "the end line is malformed", false;
    char expected[17];
    std::snprintf(expected, sizeof expected, "%016" PRIx64, fnv1a(text, endLine + 1));
    if (std::strcmp(expected, checksum) != 0)
        return reason = "the checksum does not match (file changed or partly written)", false;
    std::istringstream lines(text.substr(0, endLine + 1));
    std::string line;
    std::getline(lines, line);  // header
    if (!std::getline(lines, line) || line.compare(0, 5, "cell ") != 0)
        return reason = "the cell line is missing", false;
    cell = line.substr(5);
    for (int number = 3; std::getline(lines, line); ++number) {
        MachineDataStore::Entry entry;
        if (!parseEntry(line, entry))
            return reason = "line " + std::to_string(number) + " is not a value line", false;
        entries.push_back(entry);
    }
    if (entries.size() != count)
        return reason = "the number of values does not match the end line", false;
    return true;
}

void MachineDataFile::keepAside(MachineDataLoadResult& result) const {
    const std::string aside = asideName(path_);
    if (std::rename(path_.c_str(), aside.c_str()) == 0) {
        result.keptAside = true;
        result.asidePath = aside;
        return;
    }
    result.mayOverwrite = false;
    result.diagnostics.error("MD_FILE_KEEP_ASIDE", {},
                             "cannot rename " + path_ + " to " + aside + ": " +
                                 std::strerror(errno) +
                                 "; the machine data will not be saved over it");
}

MachineDataLoadResult MachineDataFile::load(MachineDataStore& store) const {
    MachineDataLoadResult result;
    removeStaleTemporaries(path_, result.diagnostics);
    if (!fileExists(path_)) return result;
    result.fileFound = true;
    std::string text, reason, cell;
    std::vector<MachineDataStore::Entry> entries;
    if (!readFileText(path_, text, reason, kMaxFileSize)) {
        result.mayOverwrite = false;
        result.diagnostics.error("MD_FILE_UNREADABLE", {},
                                 "cannot read machine data file " + reason +
                                     "; defaults are used and nothing will be saved over it");
        return result;
    }
    if (!parse(text, cell, entries, reason)) {
        store.resetToDefaults();
        keepAside(result);
        result.diagnostics.warning(
            "MD_FILE_DAMAGED", {},
            "machine data file " + path_ + " is damaged: " + reason + "; defaults loaded" +
                (result.keptAside ? "; the damaged file is kept as " + result.asidePath : ""));
        return result;
    }
    if (cell != store.cellName())
        result.diagnostics.warning("MD_FILE_OTHER_CELL", {},
                                   "machine data file " + path_ + " was written for cell '" + cell +
                                       "', this is '" + store.cellName() + "'");
    const std::vector<MachineDataStore::Entry> rejected = store.restore(entries);
    if (rejected.empty()) return result;
    keepAside(result);
    std::vector<std::string> details;
    for (const MachineDataStore::Entry& e : rejected)
        details.push_back(describe(e));
    result.diagnostics.warning(
        "MD_FILE_VALUES_IGNORED", {},
        std::to_string(rejected.size()) + " value(s) of " + path_ +
            " do not fit this machine (page, element or range) and were not loaded" +
            (result.keptAside ? "; the file is kept as " + result.asidePath : ""),
        details);
    return result;
}

bool MachineDataFile::save(const MachineDataStore& store, std::string& error) const {
    return writeFileAtomically(path_, serialize(store), error);
}

}  // namespace mtc::core
