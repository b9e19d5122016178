#include "cnc_core/machine_data/MachineDataLocation.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace mtc::core {
namespace {

std::string fileNameFor(const std::string& cellName) {
    std::string name;
    for (char c : cellName) {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                           (c >= '0' && c <= '9') || c == '-' || c == '_';
        name += plain ? c : '_';
    }
    return (name.empty() ? "cell" : name) + ".mdt";
}

}  // namespace

std::string defaultMachineDataPath(const std::string& cellName) {
    const char* state = std::getenv("XDG_STATE_HOME");
    std::string base;
    if (state && *state == '/') {
        base = state;
    } else {
        const char* home = std::getenv("HOME");
        if (!home || *home != '/') return "";
        base = std::string(home) + "/.local/state";
    }
    return base + "/mtc200/machine-data/" + fileNameFor(cellName);
}

bool makeParentDirectories(const std::string& path, std::string& error) {
    for (std::size_t slash = path.find('/', 1); slash != std::string::npos;
         slash = path.find('/', slash + 1)) {
        const std::string directory = path.substr(0, slash);
        if (::mkdir(directory.c_str(), 0755) != 0 && errno != EEXIST) {
            error = "cannot create directory " + directory + ": " + std::strerror(errno);
            return false;
        }
    }
    return true;
}

}  // namespace mtc::core
