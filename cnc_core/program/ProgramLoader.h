#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/program/ProgramStore.h"

namespace mtc::core {

/// True for the names of files the product writes in a program directory
/// (`*.DAT`, `*.NCO`, `*.ERR`, NC_OPTIONS.CFG, GLOBAL_MACROS.MAC, the user
/// compilers' exchange files): their stale temporaries are removed on load.
bool isProgramDirectoryFile(std::string_view name);

/// Fills a ProgramStore from program files named NuxxYzzz.DAT: a program
/// goes to (process y, number zzz); a cycle (%MAC header) goes to the cycle
/// memory under its file name without extension. Files are taken in name
/// order; when two files name the same process and number (different plant
/// or package), the first wins and the second gets FILE_DUPLICATE_PROGRAM.
/// Each program keeps its own parse diagnostics; the loader's list holds the
/// file-level problems (unreadable files, names outside the seed naming).
class ProgramLoader {
  public:
    explicit ProgramLoader(ProgramStore& store) : store_(store) {}

    /// Loads every *.DAT file of `directory` (other files are ignored; a
    /// .DAT file with another name gets FILE_BAD_NAME and is skipped; a
    /// folder, FIFO or device named *.DAT gets FILE_UNREADABLE). First
    /// removes the temporary files of saves killed before their rename
    /// (FILE_STALE_TEMPORARY, older than a minute; docs/decisions/config-files.md).
    /// Returns how many programs were stored; a missing or unreadable
    /// directory gives FILE_UNREADABLE and 0.
    std::size_t loadDirectory(const std::string& directory);

    /// Loads (file name, file text) pairs, e.g. the embedded demo programs
    /// (resources/programs/N1010001.DAT ...). Path prefixes of the names are
    /// ignored. Returns how many programs were stored.
    std::size_t loadTexts(const std::vector<std::pair<std::string, std::string>>& files);

    /// Global macro names every later load parses with (ParseOptions::macroNames).
    void setMacroNames(std::vector<std::string> names) { macroNames_ = std::move(names); }

    /// File-level problems found so far.
    const DiagnosticList& diagnostics() const { return diagnostics_; }

  private:
    bool store(const std::string& fileName, std::string text);

    ProgramStore& store_;
    DiagnosticList diagnostics_;
    std::vector<std::string> macroNames_;
};

}  // namespace mtc::core
