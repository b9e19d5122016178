#include "cnc_core/program/ProgramStore.h"

namespace mtc::core {

void ProgramStore::put(int process, int number, ProgramPtr program) {
    programs_[{process, number}] = std::move(program);
    runtime_.erase({process, number});
}

void ProgramStore::putRuntime(int process, int number, ProgramPtr program) {
    if (program)
        runtime_[{process, number}] = std::move(program);
    else
        runtime_.erase({process, number});
}

ProgramPtr ProgramStore::findRuntime(int process, int number) const {
    auto it = runtime_.find({process, number});
    return it == runtime_.end() ? nullptr : it->second;
}

ProgramPtr ProgramStore::findSource(int process, int number) const {
    auto it = programs_.find({process, number});
    return it == programs_.end() ? nullptr : it->second;
}

void ProgramStore::putCycle(const std::string& name, ProgramPtr program) {
    cycles_[name] = std::move(program);
}

ProgramPtr ProgramStore::find(int process, int number) const {
    if (ProgramPtr runtime = findRuntime(process, number)) return runtime;
    return findSource(process, number);
}

bool ProgramStore::findLabel(int process, const ProgramPtr& current, std::string_view label,
                             ProgramPtr& program, std::uint32_t& block) const {
    auto search = [&](const ProgramPtr& candidate) {
        if (!candidate) return false;
        const long found = candidate->findLabel(label);
        if (found < 0) return false;
        program = candidate;
        block = static_cast<std::uint32_t>(found);
        return true;
    };
    if (search(current) || search(library(process))) return true;
    for (const auto& entry : cycles_)
        if (search(entry.second)) return true;
    return false;
}

}  // namespace mtc::core
