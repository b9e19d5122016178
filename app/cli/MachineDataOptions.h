#pragma once

#include <string>
#include <string_view>

namespace mtc::cli {

/// Options of `md get` / `md set` (CLI-CONTRACT.md, docs/CLI.md).
struct MachineDataOptions {
    std::string writer = "gui";  ///< --as nc|sps|gui: who writes (default: the operator)
    std::string password;        ///< --password PW (operator writes of protected elements)
    std::string dataFile;        ///< --data FILE; "-" = keep nothing; empty = default location
    int sub = -1;                ///< --sub N (page 61: 1 = M(16), 2 = Q); -1 = not given
    bool given = false;          ///< one of the options was on the command line

    /// Takes the value of one of the options above. Returns "" or the usage
    /// error (bad writer, sub not 0..99, empty file or password).
    std::string take(std::string_view name, const std::string& value);
    /// Only --data was given (what `run` accepts: the file its MTD writes go to).
    bool onlyDataFile() const {
        return !dataFile.empty() && writer == "gui" && password.empty() && sub < 0;
    }
};

/// True for --as, --password, --data and --sub.
bool isMachineDataOption(std::string_view name);

}  // namespace mtc::cli
