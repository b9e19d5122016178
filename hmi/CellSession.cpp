#include "hmi/CellSession.h"

namespace mtc::hmi {

CellSession::CellSession(mtc::core::MachineConfig config, QObject* parent)
    : QObject(parent), config_(std::move(config)) {
    for (const auto& p : config_.processes) {
        controls_.push_back(std::make_unique<mtc::core::ProcessControl>(p.index));
        programs_.emplace_back();
    }
}

const mtc::core::ProcessConfig& CellSession::processConfig(int slot) const {
    return config_.processes.at(static_cast<size_t>(slot));
}

void CellSession::addProgram(int slot, ProgramSource program) {
    auto& map = programs_.at(static_cast<size_t>(slot));
    const int number = program.number;
    map[number] = std::move(program);
    emit processChanged(slot);
}

std::vector<const ProgramSource*> CellSession::programs(int slot) const {
    std::vector<const ProgramSource*> list;
    for (const auto& [number, source] : programs_.at(static_cast<size_t>(slot)))
        list.push_back(&source);
    return list;
}

const ProgramSource* CellSession::program(int slot, int number) const {
    const auto& map = programs_.at(static_cast<size_t>(slot));
    auto it = map.find(number);
    return it == map.end() ? nullptr : &it->second;
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
