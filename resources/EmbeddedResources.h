#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

/// Files compiled into the binaries: the demo cell and the demo programs.
/// Names are paths relative to resources/, e.g. "machines/demo-cell.cfg".
namespace mtc::resources {

struct EmbeddedFile {
    const char* name;
    const unsigned char* data;
    std::size_t size;
};

/// The contents of the embedded file `name`; empty and found=false when absent.
std::string_view find(std::string_view name, bool* found = nullptr);

/// Names of every embedded file whose name starts with `prefix`, sorted.
std::vector<std::string> list(std::string_view prefix);

/// The built-in demo programs as (file name, text) pairs, ready for
/// mtc::core::ProgramLoader::loadTexts. Shared by the panel and the CLI.
std::vector<std::pair<std::string, std::string>> demoPrograms();

/// The built-in demo cell of MACHINES.md.
inline constexpr std::string_view kDemoCellName = "machines/demo-cell.cfg";

}  // namespace mtc::resources
