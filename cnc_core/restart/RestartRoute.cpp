#include "cnc_core/restart/RestartRoute.h"

#include <string>

namespace mtc::core {

namespace {

/// A program level on the way to the target: where it was entered and the
/// call that opened it (none for level 0).
struct Level {
    ProgramPtr program;
    std::uint32_t entry = 0;
    std::optional<CallFrame> call;
};

std::string refText(const BlockRef& ref) {
    return "program " + std::to_string(ref.program) + " block " + std::to_string(ref.block);
}

class RoutePlanner {
  public:
    RoutePlanner(const RestartSelection& s, const ProgramStore& store, RestartRoute& route,
                 DiagnosticList& diagnostics)
        : s_(s), store_(store), route_(route), d_(diagnostics) {}

    bool plan() {
        if (s_.runs < kMinRuns || s_.runs > kMaxRuns)
            return fail("RESTART_RUNS_RANGE", {s_.mainProgram, "", 0, 0},
                        "the number of runs must be 1 .. 65536, not " + std::to_string(s_.runs));
        ProgramPtr main = program({s_.mainProgram, 0}, false);
        if (!main) return false;
        levels_.push_back({main, 0, std::nullopt});
        current_ = main;
        for (std::size_t i = 0; i < s_.path.size(); ++i)
            if (!step(s_.path[i], i + 1 < s_.path.size() ? s_.path[i + 1] : s_.target))
                return false;
        route_.targetProgram = program(s_.target, true);
        if (!route_.targetProgram) return false;
        if (route_.targetProgram->blocks[s_.target.block].flags & kBlockProgramEnd)
            return fail("RESTART_BLOCK_RANGE", locationOf(*route_.targetProgram, s_.target.block),
                        "PROGRAMMENDE cannot be the target block: the last target is the block "
                        "before the end of the program (seed 000, 2.3)");
        if (route_.targetProgram != current_)
            return fail("RESTART_PATH_INCONSISTENT",
                        locationOf(*route_.targetProgram, s_.target.block),
                        "the target lies in program " + std::to_string(s_.target.program) +
                            ", but the path ends in program " + std::to_string(current_->number) +
                            " (a block of another program is reached through a jump or call)");
        route_.selected = levels_.front().program;
        route_.targetChain.clear();
        for (std::size_t k = 1; k < levels_.size(); ++k)
            route_.targetChain.push_back(
                {levels_[k].call->program->number, levels_[k].call->callBlock});
        route_.startProgram = route_.selected;
        route_.startBlock = 0;
        route_.primary = false;
        route_.startFrames.clear();
        if (s_.fromLastPrimary) findPrimaryStart();
        return true;
    }

  private:
    bool fail(const char* code, SourceLocation where, std::string message) {
        d_.error(code, std::move(where), std::move(message));
        return false;
    }

    /// The program of `ref`, checked: it exists, is not a cycle, and (when
    /// `checkBlock`) has block `ref.block`.
    ProgramPtr program(const BlockRef& ref, bool checkBlock) {
        ProgramPtr p = store_.find(s_.process, ref.program);
        if (!p) {
            fail("RESTART_PROGRAM_NOT_FOUND", {ref.program, "", 0, 0},
                 "program " + std::to_string(ref.program) + " does not exist in process " +
                     std::to_string(s_.process));
            return nullptr;
        }
        if (p->isCycle) {
            fail("RESTART_IN_CYCLE", {ref.program, "", 0, 0},
                 "target and start block cannot be selected inside a cycle (seed 000, 2.5)");
            return nullptr;
        }
        if (checkBlock && ref.block >= p->blocks.size()) {
            fail("RESTART_BLOCK_RANGE", {ref.program, "", 0, 0},
                 refText(ref) + " lies outside the program (" + std::to_string(p->blocks.size()) +
                     " blocks)");
            return nullptr;
        }
        return p;
    }

    bool step(const BlockRef& ref, const BlockRef& next) {
        ProgramPtr p = program(ref, true);
        ProgramPtr destination = p ? program(next, false) : nullptr;
        if (!destination) return false;
        const std::optional<Word> word = jumpWordOf(*p, ref.block);
        const PathStepKind kind = word ? pathStepKind(word->jump) : PathStepKind::None;
        if (kind == PathStepKind::None)
            return fail("RESTART_PATH_NOT_A_CALL", locationOf(*p, ref.block),
                        "the path goes on from a block without a jump or call that <Plane+> "
                        "can follow");
        if (p != current_)
            return fail("RESTART_PATH_INCONSISTENT", locationOf(*p, ref.block),
                        "the path is in program " + std::to_string(current_->number) +
                            " here, not in program " + std::to_string(p->number));
        if (!consistent(*p, ref, *word, destination)) return false;
        current_ = destination;
        if (kind == PathStepKind::Jump) {
            levels_.assign(1, {destination, 0, std::nullopt});
            return true;
        }
        if (kind == PathStepKind::Branch) return true;
        std::uint32_t entry = 0;
        const std::string_view label = p->text(word->text);
        if (word->jump == JumpKind::BSR || word->jump == JumpKind::BEV) {
            const long found = destination->findLabel(label);
            if (found < 0)
                return fail("RESTART_PATH_INCONSISTENT", locationOf(*p, ref.block),
                            "the call's label ." + std::string(label) + " is not in program " +
                                std::to_string(destination->number) + ", where the path goes on");
            entry = static_cast<std::uint32_t>(found);
        }
        levels_.push_back({destination, entry, CallFrame{p, ref.block, ref.block + 1}});
        if (levels_.size() > static_cast<std::size_t>(kMaxSearchLevels))
            return fail("RESTART_PATH_DEPTH", locationOf(*p, ref.block),
                        "the target would lie on program level " + std::to_string(levels_.size()) +
                            "; at most 10 levels (9 nested calls) are possible (seed 000, 2.5)");
        return true;
    }

    /// The path goes on in the program the jump or call really leads to:
    /// labels in the program itself, then in program 99; programs by a
    /// constant number (a variable number is the operator's entry, R-004).
    bool consistent(const Program& p, const BlockRef& ref, const Word& word,
                    const ProgramPtr& destination) {
        const bool byProgram =
            word.jump == JumpKind::JSR || word.jump == JumpKind::JEV || word.jump == JumpKind::JMP;
        if (byProgram) {
            if (word.expr >= 0 || static_cast<int>(word.number) == destination->number) return true;
            return fail(
                "RESTART_PATH_INCONSISTENT", locationOf(p, ref.block),
                "the command calls program " + std::to_string(static_cast<int>(word.number)) +
                    ", but the path goes on in program " + std::to_string(destination->number));
        }
        const std::string_view label = p.text(word.text);
        const bool here = p.findLabel(label) >= 0;
        const Program* expected = here ? &p : store_.library(s_.process).get();
        if (expected && (here || expected->findLabel(label) >= 0) &&
            expected->number == destination->number)
            return true;
        return fail("RESTART_PATH_INCONSISTENT", locationOf(p, ref.block),
                    "label ." + std::string(label) + " is not found in program " +
                        std::to_string(destination->number) +
                        ", where the path goes on (labels are searched in the program itself, "
                        "then in program 99)");
    }

    /// Searches backwards for a ':' block: first before the target on its
    /// level, then from each calling block (inclusive) outwards.
    void findPrimaryStart() {
        ProgramPtr position = route_.targetProgram;
        long from = static_cast<long>(s_.target.block) - 1;
        for (std::size_t k = levels_.size(); k-- > 0;) {
            const long lower = position == levels_[k].program ? levels_[k].entry : 0;
            for (long b = from; b >= lower; --b) {
                if (!(position->blocks[static_cast<std::size_t>(b)].flags & kBlockPrimary))
                    continue;
                route_.startProgram = position;
                route_.startBlock = static_cast<std::uint32_t>(b);
                route_.primary = true;
                for (std::size_t j = 1; j <= k; ++j)
                    route_.startFrames.push_back(*levels_[j].call);
                return;
            }
            if (k == 0) break;
            position = levels_[k].call->program;
            from = static_cast<long>(levels_[k].call->callBlock);
        }
        d_.warning("RESTART_NO_PRIMARY_BLOCK", locationOf(*route_.targetProgram, s_.target.block),
                   "there is no primary block (':') before the target; the computing process "
                   "starts at the beginning of program " +
                       std::to_string(route_.selected->number));
    }

    const RestartSelection& s_;
    const ProgramStore& store_;
    RestartRoute& route_;
    DiagnosticList& d_;
    std::vector<Level> levels_;
    ProgramPtr current_;  ///< program the path is in after the steps so far
};

}  // namespace

PathStepKind pathStepKind(JumpKind kind) {
    switch (kind) {
        case JumpKind::BRA:
        case JumpKind::BEQ:
        case JumpKind::BNE:
        case JumpKind::BPL:
        case JumpKind::BMI:
        case JumpKind::BRF:
        case JumpKind::BSE:
        case JumpKind::BTE:
        case JumpKind::BES:
        case JumpKind::BER:
            return PathStepKind::Branch;
        case JumpKind::BSR:
        case JumpKind::BEV:
        case JumpKind::JSR:
        case JumpKind::JEV:
            return PathStepKind::Call;
        case JumpKind::JMP:
            return PathStepKind::Jump;
        case JumpKind::BST:
        case JumpKind::RET:
        case JumpKind::RTS:
            return PathStepKind::None;
    }
    return PathStepKind::None;
}

std::optional<Word> jumpWordOf(const Program& program, std::uint32_t block) {
    if (block >= program.blocks.size()) return std::nullopt;
    const Block b = program.blocks[block];
    for (std::uint32_t w = b.firstWord; w < b.firstWord + b.wordCount && w < program.words.size();
         ++w) {
        const Word word = program.words[w];
        if (word.kind == WordKind::Jump) return word;
    }
    return std::nullopt;
}

SourceLocation locationOf(const Program& program, std::uint32_t block) {
    SourceLocation where;
    where.program = program.number;
    if (block < program.blocks.size()) {
        where.block = program.blockId(block);
        where.line = static_cast<int>(program.blocks[block].line);
    }
    return where;
}

bool planRestartRoute(const RestartSelection& selection, const ProgramStore& store,
                      RestartRoute& route, DiagnosticList& diagnostics) {
    return RoutePlanner(selection, store, route, diagnostics).plan();
}

bool callStackMatches(const std::vector<CallFrame>& stack, const std::vector<RouteFrame>& chain) {
    if (stack.size() != chain.size()) return false;
    for (std::size_t i = 0; i < stack.size(); ++i)
        if (!stack[i].program || stack[i].program->number != chain[i].program ||
            stack[i].callBlock != chain[i].callBlock)
            return false;
    return true;
}

}  // namespace mtc::core
