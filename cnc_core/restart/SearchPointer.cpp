#include "cnc_core/restart/SearchPointer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cnc_core/language/Keywords.h"
#include "cnc_core/machine/EventTable.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {

namespace {

/// Bound of the breadcrumb (branches do not count as program levels but
/// every <Plane+> is a step <Plane-> can undo).
constexpr std::size_t kMaxPlaneSteps = 32;

bool isCall(JumpKind kind) {
    return kind == JumpKind::BSR || kind == JumpKind::JSR || kind == JumpKind::BEV ||
           kind == JumpKind::JEV;
}

std::string formatNumber(double value) {
    return formatGeneral(value, 10);
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
        text.remove_suffix(1);
    return text;
}

}  // namespace

SearchPointer::SearchPointer(const ProgramStore& store, int process, SearchSources sources)
    : store_(store), process_(process), sources_(std::move(sources)) {}

const ProgramScan& SearchPointer::scan(const ProgramPtr& program) const {
    auto& slot = scans_[program.get()];
    if (!slot) slot = std::make_unique<ProgramScan>(program);
    return *slot;
}

SourceLocation SearchPointer::where(const SearchLevel& level, std::uint32_t block) const {
    SourceLocation location;
    location.program = level.program->number;
    if (block < level.program->blocks.size()) {
        location.block = level.program->blockId(block);
        location.line = static_cast<int>(level.program->blocks[block].line);
    }
    return location;
}

SearchReply SearchPointer::refuse(std::string code, std::string message) const {
    Diagnostic d;
    d.code = std::move(code);
    d.message = std::move(message);
    if (active()) d.where = where(current(), current().cursor);
    return {false, d};
}

SearchReply SearchPointer::begin(int number) {
    ProgramPtr program = store_.find(process_, number);
    if (number == 0 || !program)
        return refuse("RESTART_NO_PROGRAM",
                      number == 0 ? "no program is selected: select the program to restart first"
                                  : "program " + std::to_string(number) + " does not exist");
    if (program->isCycle)
        return refuse("RESTART_CYCLE", "target and start block cannot be selected in a cycle");
    if (program->blocks.empty() ||
        (program->blocks.size() == 1 && (program->blocks[0].flags & kBlockProgramEnd)))
        return refuse("RESTART_EMPTY_PROGRAM",
                      "program " + std::to_string(number) + " has no block to restart at");
    scans_.clear();
    levels_.assign(1, SearchLevel{program, 0, 0, JumpKind::BRA, false});
    cancelWindow();
    fromLastPrimary_ = false;
    runs_ = kMinRuns;
    variableChanges_.clear();
    eventChanges_.clear();
    return {};
}

// ------------------------------------------------------------------ cursor

void SearchPointer::moveTo(std::uint32_t block) {
    if (!active()) return;
    cancelWindow();
    levels_.back().cursor = std::min(block, currentScan().lastSelectableBlock());
}

void SearchPointer::up() {
    if (active() && current().cursor > 0) moveTo(current().cursor - 1);
}

void SearchPointer::down() {
    if (active()) moveTo(current().cursor + 1);
}

void SearchPointer::pageUp(std::uint32_t rows) {
    if (active()) moveTo(current().cursor > rows ? current().cursor - rows : 0);
}

void SearchPointer::pageDown(std::uint32_t rows) {
    if (!active()) return;
    const std::uint64_t target = static_cast<std::uint64_t>(current().cursor) + rows;
    moveTo(static_cast<std::uint32_t>(std::min<std::uint64_t>(target, UINT32_MAX)));
}

void SearchPointer::home() {
    moveTo(0);
}

void SearchPointer::end() {
    if (active()) moveTo(currentScan().lastSelectableBlock());
}

void SearchPointer::cancelWindow() {
    window_ = {};
    pending_.reset();
}

// ------------------------------------------------------------------ Plane+/-

bool SearchPointer::readJump(const ProgramPtr& program, std::uint32_t block,
                             SearchJump& jump) const {
    const long index = scan(program).jumpWordOf(block);
    if (index < 0) return false;
    const Word word = program->words[static_cast<std::size_t>(index)];
    jump.kind = word.jump;
    jump.block = block;
    jump.label = std::string(program->text(word.text));
    if (word.jump == JumpKind::JSR || word.jump == JumpKind::JMP || word.jump == JumpKind::JEV) {
        jump.label.clear();
        if (word.expr >= 0) {
            const ExprNode& node = program->expressions[static_cast<std::size_t>(word.expr)];
            jump.byVariable = node.op == ExprOp::Variable;
            jump.variableProcess = node.process < 0 ? process_ : node.process;
            jump.variable = node.index;
        } else {
            jump.program = static_cast<int>(word.number);
        }
    }
    if (word.eventNumber >= 0) {
        jump.hasEvent = true;
        jump.event =
            EventRef{word.eventProcess < 0 ? process_ : word.eventProcess, word.eventNumber};
    }
    return true;
}

std::string SearchPointer::levelCommand(std::size_t level) const {
    if (level == 0 || level >= levels_.size()) return {};
    const SearchLevel& caller = levels_[level - 1];
    SearchJump jump;
    if (!readJump(caller.program, caller.cursor, jump)) return {};
    std::string text(jumpName(jump.kind));
    if (!jump.label.empty()) text += " ." + jump.label;
    if (jump.byVariable)
        text += " @" +
                (jump.variableProcess == process_ ? std::string()
                                                  : std::to_string(jump.variableProcess) + ":") +
                std::to_string(jump.variable);
    else if (jump.label.empty())
        text += " " + std::to_string(jump.program);
    if (jump.hasEvent)
        text += " " + std::to_string(jump.event.process) + ":" + std::to_string(jump.event.event);
    return text;
}

SearchReply SearchPointer::planePlus() {
    if (!active()) return refuse("RESTART_NO_PROGRAM", "no program is displayed");
    cancelWindow();
    SearchJump jump;
    if (!readJump(current().program, current().cursor, jump))
        return refuse("RESTART_NO_JUMP",
                      "the block has no jump or call for <Plane+> to follow (seed 000, 2.5)");
    switch (jump.kind) {
        case JumpKind::BST:
        case JumpKind::RET:
            return refuse("RESTART_PROGRAM_END",
                          std::string(jumpName(jump.kind)) +
                              " ends the program: the computing process would stop there with "
                              "'target block cannot be found' (seed 000, 2.7)");
        case JumpKind::RTS:
            return refuse("RESTART_NO_JUMP",
                          "RTS returns from a subroutine: use <Plane-> to go back to the caller");
        default:
            break;
    }
    if (isCall(jump.kind) && programLevels().size() >= static_cast<std::size_t>(kMaxSearchLevels))
        return refuse("RESTART_LEVEL_LIMIT",
                      "the target can be at most on the 10th program level (9 nested calls, "
                      "seed 000, 2.5)");
    if (levels_.size() > kMaxPlaneSteps)
        return refuse("RESTART_LEVEL_LIMIT",
                      "at most " + std::to_string(kMaxPlaneSteps) +
                          " <Plane+> steps are kept: go back with <Plane-> first");
    if (jump.hasEvent) return openEventWindow(jump);
    return follow(jump);
}

SearchReply SearchPointer::openEventWindow(const SearchJump& jump) {
    if (!EventTable::valid(jump.event.process, jump.event.event))
        return refuse("RESTART_EVENT_INVALID", "event " + std::to_string(jump.event.process) + ":" +
                                                   std::to_string(jump.event.event) +
                                                   " does not exist (process 0..6, event 0..255)");
    auto changed = eventChanges_.find(jump.event);
    window_ = {};
    window_.kind = PlaneWindow::Kind::Event;
    window_.jump = jump.kind;
    window_.event = jump.event;
    window_.eventSet =
        changed != eventChanges_.end()
            ? changed->second
            : (sources_.readEvent && sources_.readEvent(jump.event.process, jump.event.event));
    pending_ = jump;
    return {};
}

SearchReply SearchPointer::follow(const SearchJump& jump) {
    if (!jump.label.empty()) return enterLabel(jump);
    if (!jump.byVariable) return enterProgram(jump, jump.program);
    auto changed = variableChanges_.find(jump.variable);
    window_ = {};
    window_.kind = PlaneWindow::Kind::Variable;
    window_.jump = jump.kind;
    window_.variableProcess = jump.variableProcess;
    window_.variable = jump.variable;
    window_.writable = jump.variableProcess == process_;
    if (window_.writable && changed != variableChanges_.end()) {
        window_.value = changed->second;
        window_.valueKnown = true;
    } else if (sources_.readVariable) {
        window_.valueKnown =
            sources_.readVariable(jump.variableProcess, jump.variable, window_.value);
    }
    pending_ = jump;
    return {};
}

SearchReply SearchPointer::confirmEvent(bool set) {
    if (window_.kind != PlaneWindow::Kind::Event || !pending_)
        return refuse("RESTART_NO_WINDOW", "no event window is open");
    const SearchJump jump = *pending_;
    const auto saved = eventChanges_;
    const bool current =
        sources_.readEvent && sources_.readEvent(jump.event.process, jump.event.event);
    if (set == current)
        eventChanges_.erase(jump.event);
    else
        eventChanges_[jump.event] = set;
    cancelWindow();
    SearchReply reply = follow(jump);
    if (!reply.ok) eventChanges_ = saved;
    return reply;
}

SearchReply SearchPointer::confirmVariable(double value) {
    if (window_.kind != PlaneWindow::Kind::Variable || !pending_)
        return refuse("RESTART_NO_WINDOW", "no variable window is open");
    const SearchJump jump = *pending_;
    const std::string name = "@" + std::to_string(jump.variable);
    if (!std::isfinite(value) || value != std::floor(value) || value < 1 || value > 99999999)
        return refuse("RESTART_VARIABLE_VALUE",
                      name + " = " + formatNumber(value) + " is not a program number");
    const bool changed = !window_.valueKnown || value != window_.value;
    if (changed && !window_.writable)
        return refuse("RESTART_VARIABLE_READONLY",
                      "@" + std::to_string(jump.variableProcess) + ":" +
                          std::to_string(jump.variable) +
                          " belongs to another process and cannot be changed here");
    const int number = static_cast<int>(value);
    if (!store_.find(process_, number))
        return refuse("RESTART_PROGRAM_MISSING", name + " = " + std::to_string(number) +
                                                     ": program " + std::to_string(number) +
                                                     " does not exist in process " +
                                                     std::to_string(process_));
    double source = 0.0;
    const bool known =
        sources_.readVariable && sources_.readVariable(jump.variableProcess, jump.variable, source);
    const auto saved = variableChanges_;
    if (window_.writable) {
        if (known && source == value)
            variableChanges_.erase(jump.variable);
        else
            variableChanges_[jump.variable] = value;
    }
    cancelWindow();
    SearchReply reply = enterProgram(jump, number);
    if (!reply.ok) variableChanges_ = saved;
    return reply;
}

bool SearchPointer::resolveLabel(std::string_view name, const ProgramPtr& current,
                                 ProgramPtr& program, std::uint32_t& block) const {
    return store_.findLabel(process_, current, name, program, block);
}

SearchReply SearchPointer::enterLabel(const SearchJump& jump) {
    ProgramPtr program;
    std::uint32_t block = 0;
    if (!resolveLabel(jump.label, current().program, program, block))
        return refuse("RESTART_LABEL_NOT_FOUND",
                      "label ." + jump.label + " is neither in program " +
                          std::to_string(current().program->number) + " nor in program 99");
    return openLevel(jump, program, block);
}

SearchReply SearchPointer::enterProgram(const SearchJump& jump, int number) {
    ProgramPtr program = store_.find(process_, number);
    if (!program)
        return refuse("RESTART_PROGRAM_MISSING", "program " + std::to_string(number) +
                                                     " does not exist in process " +
                                                     std::to_string(process_));
    return openLevel(jump, program, 0);
}

SearchReply SearchPointer::openLevel(const SearchJump& jump, ProgramPtr program,
                                     std::uint32_t block) {
    if (program->isCycle)
        return refuse("RESTART_CYCLE",
                      std::string(jumpName(jump.kind)) +
                          " leads into a cycle: target and start block cannot be selected in a "
                          "cycle (seed 000, 2.5)");
    if (program->blocks.empty())
        return refuse("RESTART_EMPTY_PROGRAM",
                      "program " + std::to_string(program->number) + " has no blocks");
    SearchLevel level{program, 0, 0, jump.kind, isCall(jump.kind)};
    level.entry = std::min(block, scan(program).lastSelectableBlock());
    level.cursor = level.entry;
    levels_.push_back(level);
    cancelWindow();
    return {};
}

SearchReply SearchPointer::planeMinus() {
    if (!active()) return refuse("RESTART_NO_PROGRAM", "no program is displayed");
    cancelWindow();
    if (levels_.size() <= 1)
        return refuse("RESTART_TOP_LEVEL",
                      "the selected program is the first level: there is no calling point");
    levels_.pop_back();
    return {};
}

// ------------------------------------------------------------------ search, start, runs

SearchReply SearchPointer::search(std::string_view text) {
    if (!active()) return refuse("RESTART_NO_PROGRAM", "no program is displayed");
    if (text.empty()) return refuse("RESTART_SEARCH_EMPTY", "enter the text to search for");
    const auto hit = currentScan().findTextAfter(current().cursor, text);
    if (!hit) {
        const SearchLevel& level = current();
        const std::string block = level.program->blockId(level.cursor);
        return refuse("RESTART_TEXT_NOT_FOUND", "'" + std::string(text) + "' not found after " +
                                                    (block.empty() ? "the cursor" : block) +
                                                    " up to the end of program " +
                                                    std::to_string(level.program->number));
    }
    moveTo(*hit);
    return {};
}

std::vector<LevelSegment> SearchPointer::programSegments() const {
    std::vector<LevelSegment> segments;
    if (!active()) return segments;
    segments.push_back({{ProgramLevel{levels_[0].program, 0, nullptr, 0}}, nullptr, 0});
    for (std::size_t i = 1; i < levels_.size(); ++i) {
        const SearchLevel& level = levels_[i];
        if (level.call) {
            segments.back().levels.push_back(
                {level.program, level.entry, levels_[i - 1].program, levels_[i - 1].cursor});
        } else if (level.via == JumpKind::JMP) {
            segments.back().jumpProgram = levels_[i - 1].program;
            segments.back().jumpBlock = levels_[i - 1].cursor;
            segments.push_back({{ProgramLevel{level.program, 0, nullptr, 0}}, nullptr, 0});
        }
    }
    return segments;
}

std::vector<ProgramLevel> SearchPointer::programLevels() const {
    std::vector<LevelSegment> segments = programSegments();
    return segments.empty() ? std::vector<ProgramLevel>{} : std::move(segments.back().levels);
}

std::optional<StartBlock> SearchPointer::startBlock() const {
    if (!active()) return std::nullopt;
    const std::vector<LevelSegment> segments = programSegments();
    // Without the primary block the computing process starts at N0000 of the
    // selected (main) program, also for a target behind a JMP (R-024).
    if (!fromLastPrimary_)
        return StartBlock{0, BlockRef{segments.front().levels.front().program->number, 0}, false};
    // The one rule of the computing process (R-002): backwards from the
    // target on its level, then from each call (inclusive) outwards, then
    // before each JMP; with the screen's primary index for the look-ups.
    const auto lookup = [this](const ProgramPtr& program, std::uint32_t first, std::uint32_t end) {
        return scan(program).lastPrimaryIn(first, end);
    };
    const auto found = findLastPrimaryBlock(segments, current().program, current().cursor, lookup);
    if (!found) return std::nullopt;
    return StartBlock{found->level, BlockRef{found->program->number, found->block}, true};
}

SearchReply SearchPointer::setFromLastPrimary(bool on) {
    if (!active()) return refuse("RESTART_NO_PROGRAM", "no program is displayed");
    const bool before = fromLastPrimary_;
    fromLastPrimary_ = on;
    if (on && !startBlock()) {
        fromLastPrimary_ = before;
        return refuse("RESTART_NO_PRIMARY",
                      "there is no primary block (':') before the target: the computing process "
                      "starts at N0000");
    }
    return {};
}

SearchReply SearchPointer::setRuns(std::string_view text) {
    const std::string_view value = trimmed(text);
    const bool digits = !value.empty() && std::all_of(value.begin(), value.end(),
                                                      [](char c) { return c >= '0' && c <= '9'; });
    if (!digits)
        return refuse("RESTART_RUNS_TEXT", "number of runs: '" + std::string(text) +
                                               "' is not a whole number (1 ... 65536)");
    std::uint64_t runs = 0;
    for (char c : value) {
        runs = runs * 10 + static_cast<std::uint64_t>(c - '0');
        if (runs > kMaxRuns) break;
    }
    if (runs < kMinRuns || runs > kMaxRuns)
        return refuse("RESTART_RUNS_RANGE",
                      "number of runs must be 1 ... 65536, not " + std::string(value));
    runs_ = static_cast<std::uint32_t>(runs);
    return {};
}

// ------------------------------------------------------------------ accept

AcceptResult SearchPointer::accept() const {
    AcceptResult result;
    auto fail = [&](const SearchReply& reply) {
        result.diagnostics.add(*reply.note);
        return result;
    };
    if (!active()) return fail(refuse("RESTART_NO_PROGRAM", "no program is displayed"));
    if (window_.kind != PlaneWindow::Kind::None)
        return fail(refuse("RESTART_WINDOW_OPEN",
                           "close the event or variable window first (Enter or Esc)"));
    for (const SearchLevel& level : levels_)
        if (level.program->isCycle)
            return fail(
                refuse("RESTART_CYCLE", "target and start block cannot be selected in a cycle"));
    const auto start = startBlock();
    if (!start)
        return fail(refuse("RESTART_NO_PRIMARY",
                           "there is no primary block (':') before the target: switch 'restart "
                           "from last primary block' off or choose another target"));
    RestartSelection& s = result.selection;
    s.process = process_;
    s.mainProgram = levels_.front().program->number;
    for (std::size_t i = 0; i + 1 < levels_.size(); ++i)
        s.path.push_back(BlockRef{levels_[i].program->number, levels_[i].cursor});
    s.target = BlockRef{current().program->number, current().cursor};
    s.runs = runs_;
    s.fromLastPrimary = fromLastPrimary_;
    s.variableChanges = variableChanges_;
    s.eventChanges = eventChanges_;
    result.start = *start;
    result.ok = true;  // the NC's warnings (RS-011) come with ComputingProcess::begin
    return result;
}

}  // namespace mtc::core
