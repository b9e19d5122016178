#include "cnc_core/cell/Cell.h"

#include <algorithm>

#include "cnc_core/machine_data/MachineDataStore.h"

namespace mtc::core {

namespace {
/// The configuration's tool lists and zero offsets (its problems are the
/// interpreters' configuration diagnostics).
SetupData setupDataOf(const MachineConfig& config) {
    DiagnosticList ignored;
    return SetupData::fromConfig(config, ignored);
}
}  // namespace

Cell::Cell(MachineConfig config)
    : config_(std::move(config)),
      machineData_(std::make_shared<MachineDataStore>(config_)),
      events_(std::make_shared<EventTable>()),
      setupData_(setupDataOf(config_)),
      variables_(*this) {
    InterpreterServices services;
    services.machineData = machineData_;
    services.events = events_;               // one event table for every process
    services.otherProcesses = &variables_;   // @p:n reaches the other stations
    services.axisTransfer = &axisTransfer_;  // GAX / FAX of normal runs
    for (const ProcessConfig& process : config_.processes) {
        services.tools = setupData_.tools(process.index);
        services.zeroOffsets = setupData_.offsets(process.index);
        stations_.push_back(std::make_unique<Station>(process, store_, services, *machineData_));
        stations_.back()->useNcOptions(&ncOptions_);
    }
    // Start prepares the runtime program through the station's compilation.
    for (int slot = 0; slot < stationCount(); ++slot) {
        compilations_.push_back(std::make_unique<ProgramCompilation>(*this, slot));
        ProgramCompilation& compilation = *compilations_.back();
        station(slot).setPreparer([&compilation](int number, DiagnosticList& diagnostics) {
            return compilation.prepareRuntime(number, diagnostics);
        });
    }
}

Cell::~Cell() = default;

int Cell::slotOfProcess(int process) const {
    for (int slot = 0; slot < stationCount(); ++slot)
        if (station(slot).process() == process) return slot;
    return -1;
}

bool Cell::Variables::read(int process, int index, double& value) const {
    const int slot = cell_.slotOfProcess(process);
    if (slot < 0 || index < 0 || index >= kVariableCount) return false;
    value =
        cell_.station(slot).interpreter().state().variables.values[static_cast<std::size_t>(index)];
    return true;
}

bool Cell::Variables::write(int process, int index, double value) {
    const int slot = cell_.slotOfProcess(process);
    return slot >= 0 && cell_.station(slot).interpreter().writeVariable(index, value);
}

std::vector<std::string> Cell::macroNames() const {
    std::vector<std::string> names;
    for (const MacroDefinition& macro : ncOptions_.globalMacros)
        names.push_back(macro.name);
    return names;
}

ParseOptions Cell::parseOptions(int number, const std::string& name) const {
    ParseOptions options;
    options.programNumber = number;
    options.name = name;
    options.macroNames = macroNames();
    return options;
}

void Cell::setLanguage(Language language) {
    language_ = language;
    for (auto& station : stations_)
        station->setLanguage(language);
}

void Cell::setNcOptions(NcOptions options) {
    std::vector<std::string> before = macroNames();
    ncOptions_ = std::move(options);
    std::vector<std::string> after = macroNames();
    if (before == after) return;
    // A name that came or went changes how the programs naming it parse.
    std::vector<std::string> changed;
    for (const std::string& name : before)
        if (std::find(after.begin(), after.end(), name) == after.end()) changed.push_back(name);
    for (const std::string& name : after)
        if (std::find(before.begin(), before.end(), name) == before.end()) changed.push_back(name);
    reparseNaming(changed);
}

void Cell::reparseNaming(const std::vector<std::string>& names) {
    std::vector<std::pair<std::pair<int, int>, ProgramPtr>> affected;
    for (const auto& entry : store_.programs()) {
        // (No structured binding: clang's C++17 cannot capture one in a lambda.)
        const ProgramPtr& program = entry.second;
        const bool names_one = std::any_of(names.begin(), names.end(), [&](const std::string& n) {
            return program->source.view().find(n) != std::string_view::npos;
        });
        if (names_one) affected.emplace_back(entry.first, program);
    }
    for (const auto& [key, program] : affected)
        store_.put(key.first, key.second,
                   std::make_shared<Program>(
                       parseProgram(program->source, parseOptions(key.second, program->name))));
}

ProgramPtr Cell::addProgram(int slot, int number, const std::string& name, std::string text) {
    auto program =
        std::make_shared<const Program>(parseProgram(std::move(text), parseOptions(number, name)));
    putProgram(slot, number, program);
    return program;
}

void Cell::putProgram(int slot, int number, ProgramPtr program) {
    store_.put(station(slot).process(), number, std::move(program));
}

std::vector<ProgramPtr> Cell::programs(int slot) const {
    std::vector<ProgramPtr> list;
    const int process = station(slot).process();
    for (const auto& [key, program] : store_.programs())
        if (key.first == process) list.push_back(program);
    return list;
}

ProgramPtr Cell::program(int slot, int number) const {
    return store_.findSource(station(slot).process(), number);
}

void Cell::advance(double seconds, std::uint64_t maxBlocks) {
    for (auto& station : stations_)
        station->advance(seconds, maxBlocks);
}

}  // namespace mtc::core
