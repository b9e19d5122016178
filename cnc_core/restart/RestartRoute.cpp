#include "cnc_core/restart/RestartRoute.h"

#include <optional>
#include <string>

#include "cnc_core/restart/LevelReach.h"
#include "cnc_core/restart/ProgramScan.h"

namespace mtc::core {

namespace {

std::string refText(const BlockRef& ref) {
    return "program " + std::to_string(ref.program) + " block " + std::to_string(ref.block);
}

class RoutePlanner {
  public:
    RoutePlanner(const RestartSelection& s, const ProgramStore& store, RestartRoute& route,
                 DiagnosticList& diagnostics, RestartRouteCache& cache)
        : s_(s), store_(store), route_(route), d_(diagnostics), cache_(cache) {}

    bool plan() {
        if (s_.runs < kMinRuns || s_.runs > kMaxRuns)
            return fail("RESTART_RUNS_RANGE", {s_.mainProgram, "", 0, 0},
                        "the number of runs must be 1 .. 65536, not " + std::to_string(s_.runs));
        ProgramPtr main = program({s_.mainProgram, 0}, false);
        if (!main) return false;
        segments_.assign(1, LevelSegment{{ProgramLevel{main, 0, nullptr, 0}}, nullptr, 0});
        current_ = main;
        for (std::size_t i = 0; i < s_.path.size(); ++i)
            if (!step(s_.path[i], i + 1 < s_.path.size() ? s_.path[i + 1] : s_.target))
                return false;
        route_.targetProgram = program(s_.target, true);
        if (!route_.targetProgram) return false;
        route_.targetBlock = s_.target.block;
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
        const std::vector<ProgramLevel>& levels = segments_.back().levels;
        route_.main = main;
        route_.selected = levels.front().program;
        route_.targetChain.clear();
        for (std::size_t k = 1; k < levels.size(); ++k)
            route_.targetChain.push_back({levels[k].caller->number, levels[k].callBlock});
        route_.startProgram = main;
        route_.startSelected = main;
        route_.startBlock = 0;
        route_.primary = false;
        route_.startFrames.clear();
        std::optional<PrimaryStart> start;
        if (s_.fromLastPrimary) start = findPrimaryStart();
        route_.segments = segments_;
        return onTheirLevels(start);
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
        std::vector<ProgramLevel>& levels = segments_.back().levels;
        if (kind == PathStepKind::Jump) {
            segments_.back().jumpProgram = p;
            segments_.back().jumpBlock = ref.block;
            segments_.push_back({{ProgramLevel{destination, 0, nullptr, 0}}, nullptr, 0});
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
        levels.push_back({destination, entry, p, ref.block});
        if (levels.size() > static_cast<std::size_t>(kMaxSearchLevels))
            return fail("RESTART_PATH_DEPTH", locationOf(*p, ref.block),
                        "the target would lie on program level " + std::to_string(levels.size()) +
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

    /// The last ':' block before the target (R-002, across JMPs R-024).
    std::optional<PrimaryStart> findPrimaryStart() {
        std::optional<PrimaryStart> start = findLastPrimaryBlock(
            segments_, route_.targetProgram, s_.target.block, scanForPrimaryBlock);
        if (!start) {
            d_.warning("RESTART_NO_PRIMARY_BLOCK",
                       locationOf(*route_.targetProgram, s_.target.block),
                       "there is no primary block (':') before the target; the computing process "
                       "starts at the beginning of program " +
                           std::to_string(route_.main->number));
            return start;
        }
        route_.startProgram = start->program;
        route_.startBlock = start->block;
        route_.startSelected = segments_[start->segment].levels.front().program;
        route_.primary = true;
        route_.startFrames = start->frames;
        return start;
    }

    /// Every block where the path leaves a program level (a call, a JMP) and
    /// the target must be reached on that level: a block only a
    /// subroutine call runs through is refused with the call to follow.
    bool onTheirLevels(const std::optional<PrimaryStart>& start) {
        for (std::size_t s = 0; s < segments_.size(); ++s) {
            const std::vector<ProgramLevel>& levels = segments_[s].levels;
            for (std::size_t k = 0; k < levels.size(); ++k) {
                const bool last = k + 1 == levels.size();
                const bool finalSegment = s + 1 == segments_.size();
                const ProgramPtr exitProgram =
                    !last ? levels[k + 1].caller
                          : (finalSegment ? route_.targetProgram : segments_[s].jumpProgram);
                const std::uint32_t exitBlock =
                    !last ? levels[k + 1].callBlock
                          : (finalSegment ? s_.target.block : segments_[s].jumpBlock);
                if (exitProgram != levels[k].program) continue;  // a branch into program 99
                std::vector<std::uint32_t> entries{levels[k].entry};
                if (start && start->segment == s && start->level == static_cast<int>(k))
                    entries.push_back(start->block);
                const bool programStart = s == 0 && k == 0 && !route_.primary;
                if (!reachedOnLevel(levels[k].program, entries, exitBlock, last && finalSegment,
                                    programStart))
                    return false;
            }
        }
        return true;
    }

    bool reachedOnLevel(const ProgramPtr& program, const std::vector<std::uint32_t>& entries,
                        std::uint32_t block, bool isTarget, bool programStart) {
        if (cache_.reaches(program, entries, block)) return true;
        const LevelReach& reach = cache_.reach(program);
        if (programStart) {  // seed 000, 2.4: a subroutine at the start needs the start block
            const std::optional<std::uint32_t> rts = reach.returnWithoutCall();
            if (rts && *rts < block)
                return fail("RESTART_START_BLOCK_NEEDED", locationOf(*program, *rts),
                            "the program starts with a subroutine (RTS in " +
                                program->blockId(*rts) +
                                " without a call): the computing process would end there; "
                                "select 'restart from last primary block' (seed 000, 2.4)");
        }
        const auto sub = reach.subroutineOf(block);
        // Reached by no flow at all (dead code after M30): the computing process
        // answers "target block cannot be found" as seed 000, 2.7 says.
        if (!sub) return true;
        const std::string id = program->blockId(block).empty() ? "block " + std::to_string(block)
                                                               : program->blockId(block);
        const std::string call = program->blockId(sub->callBlock);
        return fail("RESTART_TARGET_IN_SUBROUTINE", locationOf(*program, block),
                    (isTarget ? "the target " : "the path block ") + id +
                        " is not reached on this program level: it belongs to the subroutine ." +
                        sub->label + " that " + call + " calls; put the cursor on " + call +
                        " and follow the call with <Plane+> (seed 000, 2.5)");
    }

    const RestartSelection& s_;
    const ProgramStore& store_;
    RestartRoute& route_;
    DiagnosticList& d_;
    RestartRouteCache& cache_;
    std::vector<LevelSegment> segments_;
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
         ++w)
        if (program.words.kindAt(w) == WordKind::Jump) return program.words[w];
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
                      RestartRoute& route, DiagnosticList& diagnostics, RestartRouteCache* cache) {
    RestartRouteCache own;
    return RoutePlanner(selection, store, route, diagnostics, cache ? *cache : own).plan();
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

namespace mtc::core {

bool atRouteLevel(const InterpreterState& state, const RestartRoute& route) {
    return state.selected == route.selected && callStackMatches(state.callStack, route.targetChain);
}

RestartRouteCache::RestartRouteCache() = default;
RestartRouteCache::~RestartRouteCache() = default;

bool RestartRouteCache::reaches(const ProgramPtr& program,
                                const std::vector<std::uint32_t>& entries, std::uint32_t block) {
    auto key = std::make_pair(program.get(), entries);
    auto found = reachable_.find(key);
    if (found == reachable_.end())
        found = reachable_.emplace(std::move(key), reach(program).reachable(entries)).first;
    return block < found->second.size() && found->second.test(block);
}

const LevelReach& RestartRouteCache::reach(const ProgramPtr& program) {
    std::unique_ptr<LevelReach>& slot = reaches_[program.get()];
    if (!slot) {
        keep_.push_back(program);
        slot = std::make_unique<LevelReach>(program);
    }
    return *slot;
}

const ProgramScan& RestartRouteCache::scan(const ProgramPtr& program) {
    std::unique_ptr<ProgramScan>& slot = scans_[program.get()];
    if (!slot) {
        keep_.push_back(program);
        slot = std::make_unique<ProgramScan>(program);
    }
    return *slot;
}

void addStartWarnings(const RestartRoute& route, DiagnosticList& diagnostics,
                      RestartRouteCache* cache) {
    if (!route.main || route.segments.empty()) return;
    if (!route.primary) {
        // The block of the main program the way passes: the call into level
        // 1, the JMP that leaves it, or the target itself.
        const LevelSegment& first = route.segments.front();
        const bool jumped = route.segments.size() > 1;
        std::optional<std::uint32_t> passed;
        if (first.levels.size() > 1 && first.levels[1].caller == route.main)
            passed = first.levels[1].callBlock;
        else if (first.levels.size() == 1 && jumped && first.jumpProgram == route.main)
            passed = first.jumpBlock;
        else if (!jumped && first.levels.size() == 1 && route.targetProgram == route.main)
            passed = route.targetBlock;
        std::optional<LevelReach> own;
        const LevelReach& reach = cache ? cache->reach(route.main) : own.emplace(route.main);
        const auto rts = reach.returnWithoutCall();
        if (rts && passed && *rts < *passed)
            diagnostics.warning(
                "RESTART_START_BLOCK_NEEDED", locationOf(*route.main, *rts),
                "the program starts with a subroutine (RTS in " + route.main->blockId(*rts) +
                    " without a call): select 'restart from last primary block', otherwise the "
                    "computing process runs into the subroutine (seed 000, 2.4)");
        return;
    }
    std::optional<ProgramScan> own;
    const ProgramScan& scan =
        cache ? cache->scan(route.startProgram) : own.emplace(route.startProgram);
    const std::uint32_t block = route.startBlock;
    if (scan.modalActiveBefore(block, 91, 90))
        diagnostics.warning("RESTART_START_AFTER_G91", locationOf(*route.startProgram, block),
                            "the start block lies after an incremental dimension G91: the "
                            "computing process starts in G90 (seed 000, 5.1)");
    if (scan.modalActiveBefore(block, 51, 50))
        diagnostics.warning("RESTART_START_AFTER_G51", locationOf(*route.startProgram, block),
                            "the start block lies after an incremental zero offset G51: the "
                            "computing process does not see it (seed 000, 5.1)");
}

}  // namespace mtc::core
