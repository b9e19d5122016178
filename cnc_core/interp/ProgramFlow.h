#pragma once

#include <cstdint>
#include <string_view>
#include <unordered_map>

#include "cnc_core/interp/BlockContext.h"
#include "cnc_core/interp/BlockInput.h"
#include "cnc_core/interp/InterpreterState.h"
#include "cnc_core/machine/EventTable.h"
#include "cnc_core/program/ProgramStore.h"

namespace mtc::core {

/// Where execution goes after a block.
struct FlowPlan {
    enum class Kind {
        Next,    ///< the following block
        Goto,    ///< continue at `program`/`block` (branch, label in program 99 or a cycle)
        Call,    ///< push a return point, continue at `program`/`block` (BSR, JSR, BEV, JEV)
        Return,  ///< RTS: pop the innermost return point
        End,     ///< BST / RET: end of program
        Jump,    ///< JMP: end of this program (plane and transformation reset), go to `program`
    };
    Kind kind = Kind::Next;
    ProgramPtr program;
    std::uint32_t block = 0;
};

/// Resolves and checks the jump word of a block (labels searched in the
/// current program, then program 99 of the process, then the cycle memory;
/// programs by number; events; the call depth of 10 levels). Resolved labels
/// are cached per program and word, so a loop does not search strings.
class ProgramFlow {
  public:
    ProgramFlow(const ProgramStore& store, int process, const EventTable* events)
        : store_(store), process_(process), events_(events) {}

    /// Decides the flow of a block whose decoded words are `input`. `next` is
    /// the modal state after the block (T for BTE, tool spindles for BSE).
    /// Returns false (error added) for a missing label or program, a call
    /// beyond level 10, RTS without call, a bad event or an unsupported branch.
    bool plan(const BlockContext& context, const BlockInput& input, const InterpreterState& state,
              const ModalState& next, FlowPlan& flow);
    /// Forgets resolved labels (call when the program store changed).
    void clearCache() { cache_.clear(); }
    /// Finds `label` as the running program would: `current`, program 99,
    /// cycle memory. Returns false when it is nowhere.
    bool findLabel(const ProgramPtr& current, std::string_view label, ProgramPtr& program,
                   std::uint32_t& block) const;

  private:
    struct Resolved {
        ProgramPtr program;
        std::uint32_t block = 0;
    };
    struct CacheEntry {
        ProgramPtr keepAlive;  ///< so that the key's address is never reused
        std::unordered_map<std::uint32_t, Resolved> words;
    };

    bool label(const BlockContext& c, const InterpreterState& state, std::uint32_t wordIndex,
               std::string_view name, int column, FlowPlan& flow);
    bool program(const BlockContext& c, double number, int column, FlowPlan& flow) const;
    bool event(const BlockContext& c, const Word& word, bool& set) const;
    bool callAllowed(const BlockContext& c, const InterpreterState& state, int column) const;

    const ProgramStore& store_;
    int process_;
    const EventTable* events_;
    std::unordered_map<const Program*, CacheEntry> cache_;
};

}  // namespace mtc::core
