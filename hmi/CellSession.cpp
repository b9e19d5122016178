#include "hmi/CellSession.h"

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/SimulatedMachine.h"
#include "hmi/SimulationClock.h"

namespace mtc::hmi {

/// Everything one process of the cell runs on.
struct CellSession::Station {
    Station(const mtc::core::ProcessConfig& config, const mtc::core::ProgramStore& store)
        : control(config.index),
          machine(config),
          interpreter(config, store, machine),
          clock(interpreter, machine, control) {
        control.setRunner(&clock);
    }
    mtc::core::ProcessControl control;
    mtc::core::SimulatedMachine machine;
    mtc::core::Interpreter interpreter;
    SimulationClock clock;
};

CellSession::CellSession(mtc::core::MachineConfig config, QObject* parent)
    : QObject(parent), config_(std::move(config)) {
    for (int slot = 0; slot < processCount(); ++slot) {
        stations_.push_back(std::make_unique<Station>(processConfig(slot), store_));
        connect(&stations_.back()->clock, &SimulationClock::changed, this,
                [this, slot] { emit processChanged(slot); });
    }
}

CellSession::~CellSession() = default;

const mtc::core::ProcessConfig& CellSession::processConfig(int slot) const {
    return config_.processes.at(static_cast<size_t>(slot));
}

mtc::core::ProcessControl& CellSession::control(int slot) {
    return stations_.at(static_cast<size_t>(slot))->control;
}

const mtc::core::ProcessControl& CellSession::control(int slot) const {
    return stations_.at(static_cast<size_t>(slot))->control;
}

mtc::core::Interpreter& CellSession::interpreter(int slot) {
    return stations_.at(static_cast<size_t>(slot))->interpreter;
}

mtc::core::SimulatedMachine& CellSession::machine(int slot) {
    return stations_.at(static_cast<size_t>(slot))->machine;
}

SimulationClock& CellSession::clock(int slot) {
    return stations_.at(static_cast<size_t>(slot))->clock;
}

int CellSession::slotOfProcess(int process) const {
    for (int slot = 0; slot < processCount(); ++slot)
        if (processConfig(slot).index == process) return slot;
    return -1;
}

void CellSession::addProgram(int slot, int number, const std::string& name, std::string text) {
    mtc::core::ParseOptions options;
    options.programNumber = number;
    options.name = name;
    putProgram(
        slot, number,
        std::make_shared<mtc::core::Program>(mtc::core::parseProgram(std::move(text), options)));
}

void CellSession::putProgram(int slot, int number, mtc::core::ProgramPtr program) {
    store_.put(processConfig(slot).index, number, std::move(program));
    emit processChanged(slot);
}

std::vector<mtc::core::ProgramPtr> CellSession::programs(int slot) const {
    std::vector<mtc::core::ProgramPtr> list;
    const int process = processConfig(slot).index;
    for (const auto& [key, program] : store_.programs())
        if (key.first == process) list.push_back(program);
    return list;
}

mtc::core::ProgramPtr CellSession::program(int slot, int number) const {
    return store_.find(processConfig(slot).index, number);
}

bool CellSession::pressKey(int slot, mtc::core::ControlKey key) {
    bool ok = control(slot).press(key);
    emit processChanged(slot);
    return ok;
}

bool CellSession::selectProgram(int slot, int number) {
    bool ok = control(slot).selectProgram(number);
    emit processChanged(slot);
    return ok;
}

}  // namespace mtc::hmi
