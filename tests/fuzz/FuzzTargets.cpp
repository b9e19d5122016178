#include "FuzzTargets.h"

#include <cstdio>
#include <cstdlib>

namespace mtc::fuzz {

const std::vector<FuzzTarget>& fuzzTargets() {
    static const std::vector<FuzzTarget> targets = {
        {"parser", "DatFile::parse as .DAT and loose text, with and without global macro names",
         fuzzParser},
        {"compiler", "Compiler, all standard passes, without and with global macros", fuzzCompiler},
        {"gne", "GNE reader, solver and expansion; written text reads back the same", fuzzGne},
        {"machine_config", "machine configuration reader; a good one builds interpreters",
         fuzzMachineConfig},
        {"machine_data", "machine data file parser and restore into the demo cell's store",
         fuzzMachineDataFile},
        {"target_path", "restart target-path resolver over fuzzed programs 1, 99, 7, 5",
         fuzzTargetPath},
        {"mdi", "MDI entry: prepareMdiEntry with global macros, then run on process 0",
         fuzzMdiEntry},
        {"removal", "material removal: a program cuts the mill's or the lathe's stock, STL",
         fuzzRemoval},
        {"reentry",
         "restart way back against the part: stock, program, ADJUST / REPOS, collision check",
         fuzzReentry},
    };
    return targets;
}

const FuzzTarget* findFuzzTarget(std::string_view name) {
    for (const FuzzTarget& target : fuzzTargets())
        if (name == target.name) return &target;
    return nullptr;
}

void require(bool condition, const char* what, std::string_view input) {
    if (condition) return;
    const std::size_t shown = input.size() < 400 ? input.size() : 400;
    std::fprintf(stderr, "fuzz contract broken: %s\ninput (%zu bytes, first %zu):\n%.*s\n", what,
                 input.size(), shown, static_cast<int>(shown), input.data());
    std::abort();
}

}  // namespace mtc::fuzz
