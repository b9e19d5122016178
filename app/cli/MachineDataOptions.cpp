#include "cli/MachineDataOptions.h"

namespace mtc::cli {

bool isMachineDataOption(std::string_view name) {
    return name == "--as" || name == "--password" || name == "--data" || name == "--sub";
}

std::string MachineDataOptions::take(std::string_view name, const std::string& value) {
    given = true;
    if (name == "--as") {
        if (value != "nc" && value != "sps" && value != "gui")
            return "bad value '" + value + "' for --as (nc, sps or gui)";
        writer = value;
    } else if (name == "--password") {
        if (value.empty()) return "--password needs a password";
        password = value;
    } else if (name == "--data") {
        if (value.empty()) return "--data needs a file (or '-' for none)";
        dataFile = value;
    } else if (name == "--sub") {
        if (value.empty() || value.size() > 2 ||
            value.find_first_not_of("0123456789") != std::string::npos)
            return "bad value '" + value + "' for --sub (0..99)";
        sub = std::stoi(value);
    }
    return "";
}

}  // namespace mtc::cli
