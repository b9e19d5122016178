#pragma once

#include <memory>
#include <string>

#include "InterpTestSupport.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/machine/InMemoryMachineData.h"
#include "cnc_core/restart/ComputingProcess.h"
#include "cnc_core/restart/RestartSelection.h"

namespace mtc::test {

/// The program and machine data helpers of a restart test's cell, one rule
/// for every fixture: `Self` has `config`, `store` and `machineData`.
template <class Self>
struct ProcessPrograms {
    /// Parses and stores program `number` (a parse error fails the test).
    core::ProgramPtr add(const std::string& source, int number) {
        core::ProgramPtr p = parse(source, number);
        EXPECT_FALSE(p->diagnostics.hasErrors()) << diagnosticsText(p->diagnostics);
        self().store.put(self().config.index, number, p);
        return p;
    }
    /// Block index of block N`number` of program `program`.
    std::uint32_t block(int program, int number) const {
        const core::ProgramPtr p = self().store.find(self().config.index, program);
        for (std::uint32_t b = 0; p && b < p->blocks.size(); ++b)
            if (p->blocks[b].number == number) return b;
        ADD_FAILURE() << "no N" << number << " in program " << program;
        return 0;
    }
    core::BlockRef ref(int program, int number) const { return {program, block(program, number)}; }
    /// A selection in main program `main` with target N`target` of `program`.
    core::RestartSelection selection(int main, int program, int target,
                                     std::uint32_t runs = 1) const {
        core::RestartSelection s;
        s.process = self().config.index;
        s.mainProgram = main;
        s.target = ref(program, target);
        s.runs = runs;
        return s;
    }
    double page(int number, int sub, int element) const {
        double value = -12345;
        self().machineData->read({number, self().config.index, sub, element}, value);
        return value;
    }

  private:
    Self& self() { return static_cast<Self&>(*this); }
    const Self& self() const { return static_cast<const Self&>(*this); }
};

/// One process of the demo cell for restart tests: program memory, shared
/// machine data and events, a recording "SPS" and the process's interpreter.
struct RestartCell : ProcessPrograms<RestartCell> {
    explicit RestartCell(int process)
        : config(*demoCell().process(process)),
          machineData(std::make_shared<core::InMemoryMachineData>(demoCell())),
          events(std::make_shared<core::EventTable>()),
          live(config, store, sps, services()) {}

    core::InterpreterServices services() {
        core::InterpreterServices s;
        s.machineData = machineData;
        s.events = events;
        return s;
    }
    const core::ProcessConfig& config;
    core::ProgramStore store;
    core::RecordingSink sps;
    std::shared_ptr<core::InMemoryMachineData> machineData;
    std::shared_ptr<core::EventTable> events;
    core::Interpreter live;
};

}  // namespace mtc::test
