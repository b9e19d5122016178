// Machine configuration reader and machine data file reader.
//  - machine_config: readMachineConfig never crashes; every diagnostic has
//    a code and a message; a configuration read without errors builds a
//    station (interpreter, machine data, adaptive feed control) for every
//    process, and a short program runs on it.
//  - machine_data: MachineDataFile::parse of the file text; what it accepts
//    is restored into the demo cell's store, and the store's own file text
//    parses back to the same entries.
#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <string>

#include "../FuzzTargets.h"
#include "DemoCell.h"
#include "FuzzStation.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/machine_data/MachineDataFile.h"

namespace mtc::fuzz {

using namespace mtc::core;

void fuzzMachineConfig(std::string_view input) {
    const MachineConfigReadResult read = readMachineConfig(input);
    for (const Diagnostic& d : read.diagnostics.items())
        require(!d.code.empty() && !d.message.empty(), "configuration diagnostics say what", input);
    if (!read.ok()) return;
    const auto program = std::make_shared<Program>(
        parseProgram("N0001 G0 G90 X1 Y1 Z1\nN0002 G1 X2 F100 S100 M3\nN0003 G4 F.1\nN0004 M30\n"));
    program->number = 1;
    for (const ProcessConfig& process : read.config.processes) {
        FuzzStation station(process, input);
        if (!station.interpreter->configurationDiagnostics().empty()) continue;
        station.store.put(process.index, 1, program);
        if (station.interpreter->select(1)) station.interpreter->run(100);
        MachineDataStore data(read.config);
        std::string cell;
        std::vector<MachineDataStore::Entry> entries;
        std::string reason;
        require(MachineDataFile::parse(MachineDataFile::serialize(data), cell, entries, reason),
                "the machine data of a good configuration is written readably", input);
    }
}

namespace {

/// The input with a correct end line: "end <lines after the cell line>
/// <FNV-1a 64 of everything before>". Without it nearly every mutation
/// would stop at the checksum and the value lines would never be read.
std::string sealed(std::string_view input) {
    std::string text(input.substr(0, std::min(input.rfind("\nend "), input.size())));
    if (text.empty() || text.back() != '\n') text += '\n';
    std::size_t lines = 0;
    for (char c : text)
        lines += c == '\n';
    std::uint64_t hash = 1469598103934665603ull;
    for (char c : text) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 1099511628211ull;
    }
    char end[64];
    std::snprintf(end, sizeof end, "end %zu %016" PRIx64 "\n", lines >= 2 ? lines - 2 : 0, hash);
    return text + end;
}

/// Parses `text`; what parses is restored into the demo cell's store, whose
/// own file text must parse back to the same store.
void parseAndRestore(const std::string& text, std::string_view input) {
    std::string cell;
    std::vector<MachineDataStore::Entry> entries;
    std::string reason;
    const bool parsed = MachineDataFile::parse(text, cell, entries, reason);
    require(parsed || !reason.empty(), "a damaged file says why", input);
    if (!parsed) return;
    MachineDataStore store(demoCell());
    store.restore(entries);
    const std::string written = MachineDataFile::serialize(store);
    std::vector<MachineDataStore::Entry> again;
    require(MachineDataFile::parse(written, cell, again, reason),
            "the store's own file text parses", input);
    MachineDataStore copy(demoCell());
    copy.restore(again);
    require(MachineDataFile::serialize(copy) == written, "the file text reads back the same",
            input);
}

}  // namespace

void fuzzMachineDataFile(std::string_view input) {
    parseAndRestore(std::string(input), input);
    parseAndRestore(sealed(input), input);
}

}  // namespace mtc::fuzz
