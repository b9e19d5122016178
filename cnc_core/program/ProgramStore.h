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
///
/// Each program has a source version (what the editor shows) and may have a
/// runtime version: the compiled object program of a source with compiler
/// keywords (seed 001 ch. 10/11, decision C-013). find() -- used by the
/// interpreter and the NC program restart -- returns the runtime version when
/// there is one, so a station and its restart always work on the same program.
class ProgramStore {
  public:
    /// Stores (or replaces) the source of program `number` of `process`; a
    /// runtime version of that number is dropped (it was compiled from the old text).
    void put(int process, int number, ProgramPtr program);
    /// Makes `program` (a compiled object program) the one the control runs
    /// for `number` of `process`; nullptr drops it (the source runs again).
    void putRuntime(int process, int number, ProgramPtr program);
    /// The runtime version set by putRuntime(), or nullptr.
    ProgramPtr findRuntime(int process, int number) const;
    /// The source version (what was put()), or nullptr.
    ProgramPtr findSource(int process, int number) const;
    /// Stores a cycle (cycle memory, shared by all processes).
    void putCycle(const std::string& name, ProgramPtr program);
    /// The program the control runs (runtime version, else source), or
    /// nullptr when the process has no such program.
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
    /// The source programs by (process, number).
    const std::map<std::pair<int, int>, ProgramPtr>& programs() const { return programs_; }

  private:
    std::map<std::pair<int, int>, ProgramPtr> programs_;
    std::map<std::pair<int, int>, ProgramPtr> runtime_;  ///< compiled versions
    std::map<std::string, ProgramPtr> cycles_;
};

}  // namespace mtc::core
