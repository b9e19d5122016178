#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>

#include "cnc_core/language/Program.h"

namespace mtc::core {

/// The control's program memory: programs by number per process, program 99
/// as the label library of a process, and the cycle memory (%MAC files) that
/// every process can reach. Programs are immutable once stored (shared_ptr to
/// const), so a computing process and a live run can share them.
class ProgramStore {
  public:
    /// Stores (or replaces) program `number` of `process`.
    void put(int process, int number, ProgramPtr program);
    /// Stores a cycle (cycle memory, shared by all processes).
    void putCycle(const std::string& name, ProgramPtr program);
    /// The program, or nullptr when the process has no such program.
    ProgramPtr find(int process, int number) const;
    /// Program 99 of the process (label library), or nullptr.
    ProgramPtr library(int process) const { return find(process, 99); }
    /// Finds `label` in the control's search order (seed 000, 2.5): the
    /// program `current`, then program 99 of `process`, then the cycle
    /// memory. Sets `program` and `block` (index) and returns true, or
    /// returns false when the label is nowhere. The one place that order lives.
    bool findLabel(int process, const ProgramPtr& current, std::string_view label,
                   ProgramPtr& program, std::uint32_t& block) const;
    const std::map<std::string, ProgramPtr>& cycles() const { return cycles_; }
    const std::map<std::pair<int, int>, ProgramPtr>& programs() const { return programs_; }

  private:
    std::map<std::pair<int, int>, ProgramPtr> programs_;
    std::map<std::string, ProgramPtr> cycles_;
};

}  // namespace mtc::core
