#include "cnc_core/program/ProgramLoader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>
#include <optional>

#include "cnc_core/program/AtomicWrite.h"
#include "cnc_core/program/DatFile.h"
#include "cnc_core/program/DatFileName.h"
#include "cnc_core/program/FileText.h"

namespace mtc::core {

namespace {

bool hasDatExtension(const std::string& name) {
    if (name.size() < 4) return false;
    std::string ext = name.substr(name.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return ext == ".DAT";
}

bool endsWithNoCase(std::string_view name, std::string_view end) {
    if (name.size() < end.size()) return false;
    for (std::size_t i = 0; i < end.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(name[name.size() - end.size() + i])) !=
            std::toupper(static_cast<unsigned char>(end[i])))
            return false;
    return true;
}

std::string baseName(const std::string& path) {
    std::size_t slash = path.find_last_of("/\\");
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

bool isProgramDirectoryFile(std::string_view name) {
    for (std::string_view end : {".DAT", ".NCO", ".ERR"})
        if (endsWithNoCase(name, end)) return true;
    return name == "NC_OPTIONS.CFG" || name == "GLOBAL_MACROS.MAC" ||
           (name.rfind("user_compiler_", 0) == 0);
}

std::size_t ProgramLoader::loadDirectory(const std::string& directory) {
    namespace fs = std::filesystem;
    std::error_code error;
    std::vector<std::string> files;
    for (const std::string& removed : removeStaleTemporaries(directory, isProgramDirectoryFile))
        diagnostics_.warning("FILE_STALE_TEMPORARY", SourceLocation{},
                             "removed " + removed +
                                 ", the unfinished temporary file of an interrupted save");
    for (fs::directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error)) {
        if (!hasDatExtension(it->path().filename().string())) continue;
        const std::string path = it->path().string();
        const std::string why = whyNotARegularFile(path);
        if (why.empty())
            files.push_back(path);
        else  // a folder, FIFO or device named *.DAT, or a dangling link
            diagnostics_.error("FILE_UNREADABLE", SourceLocation{},
                               path + " " + why + ", not a program file; skipped");
    }
    if (error) {
        diagnostics_.error("FILE_UNREADABLE", SourceLocation{},
                           "cannot read program directory " + directory + ": " + error.message());
        return 0;
    }
    std::sort(files.begin(), files.end());
    std::size_t stored = 0;
    for (const auto& path : files) {
        std::string text, why;
        if (!readFileText(path, text, why)) {
            diagnostics_.error("FILE_UNREADABLE", SourceLocation{}, why);
            continue;
        }
        stored += store(path, std::move(text)) ? 1 : 0;
    }
    return stored;
}

std::size_t ProgramLoader::loadTexts(
    const std::vector<std::pair<std::string, std::string>>& files) {
    std::vector<std::pair<std::string, std::string>> sorted(files);
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& a, const auto& b) { return baseName(a.first) < baseName(b.first); });
    std::size_t stored = 0;
    for (auto& [name, text] : sorted)
        stored += store(name, std::move(text)) ? 1 : 0;
    return stored;
}

bool ProgramLoader::store(const std::string& fileName, std::string text) {
    std::string why;
    std::string name = baseName(fileName);
    std::optional<DatFileName> id = parseDatFileName(name, &why);
    if (!id) {
        diagnostics_.error("FILE_BAD_NAME", SourceLocation{}, name + ": " + why);
        return false;
    }
    ParseOptions options;
    options.macroNames = macroNames_;
    auto program = std::make_shared<Program>(DatFile::parse(std::move(text), name, options));
    if (program->isCycle) {
        std::string cycleName = name.substr(0, name.size() - 4);
        if (store_.cycles().count(cycleName)) return false;
        store_.putCycle(cycleName, std::move(program));
        return true;
    }
    if (store_.find(id->process, id->number)) {
        diagnostics_.warning("FILE_DUPLICATE_PROGRAM", SourceLocation{id->number, "", 0, 0},
                             name + " names program " + std::to_string(id->number) +
                                 " of process " + std::to_string(id->process) +
                                 " again; the first file is kept");
        return false;
    }
    store_.put(id->process, id->number, std::move(program));
    return true;
}

}  // namespace mtc::core
