#include "cnc_core/program/ProgramStore.h"

namespace mtc::core {

void ProgramStore::put(int process, int number, ProgramPtr program) {
    programs_[{process, number}] = std::move(program);
}

void ProgramStore::putCycle(const std::string& name, ProgramPtr program) {
    cycles_[name] = std::move(program);
}

ProgramPtr ProgramStore::find(int process, int number) const {
    auto it = programs_.find({process, number});
    return it == programs_.end() ? nullptr : it->second;
}

}  // namespace mtc::core
