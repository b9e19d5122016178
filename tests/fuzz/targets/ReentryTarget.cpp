// The restart's way back against the part (issue 19 §4, D-021): the input
// makes the stock, the program and its ADJUST / REPOS subroutines of a
// restart on the demo mill or lathe (by the input's length):
//   line 1   the process's stock, as `stock = ...` of the machine
//            configuration ("block XMIN XMAX YMIN YMAX ZMIN ZMAX",
//            "cylinder Z RADIUS FROM TO", "none"), in machine coordinates
//   line 2   the target's block index in program 1, then the machine
//            positions the axes stand at when the restart is accepted
//   the rest program 1, a form feed, program 99 (.ADJUST / .REPOS)
// The restart runs to the target like the CLI's (computing process, M00
// continued with Start, 5000 blocks at most); there the way back is checked
// against the part at a coarse resolution (checkRestartReentry, as
// `restart --check-collisions` and the result review do). Contracts: a
// check at the target reached; an unchecked way back says why and lists
// nothing; a checked one lists each colliding move once, in order, at
// finite positions in blocks of stored programs, with the tolerance half
// the resolution and a finite removed volume; the check changes nothing of
// the station and says the same when asked again.
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "../FuzzTargets.h"
#include "DemoCell.h"
#include "cnc_core/cell/Cell.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/removal/ReentryCollisions.h"
#include "cnc_core/restart/RestartSequence.h"

namespace mtc::fuzz {

namespace {

using namespace mtc::core;

constexpr std::uint64_t kBlockBudget = 5'000;

/// The part of `text` up to `separator` (all of it when there is none);
/// `text` keeps what follows.
std::string_view take(std::string_view& text, char separator) {
    const std::size_t end = std::min(text.find(separator), text.size());
    const std::string_view part = text.substr(0, end);
    text = text.substr(std::min(end + 1, text.size()));
    return part;
}

/// The numbers of `line`, separated by anything strtod does not read.
std::vector<double> numbersOf(std::string_view line) {
    const std::string text(line);
    std::vector<double> numbers;
    const char* p = text.c_str();
    while (*p != '\0') {
        char* end = nullptr;
        const double value = std::strtod(p, &end);
        if (end == p) {
            ++p;
            continue;
        }
        numbers.push_back(value);
        p = end;
    }
    return numbers;
}

ProgramPtr parsed(std::string_view source, int number) {
    ParseOptions options;
    options.programNumber = number;
    auto program = std::make_shared<Program>(parseProgram(std::string(source), options));
    program->number = number;
    return program;
}

/// The computing process up to the target (or its end), M00 / M01 continued
/// with Start as the CLI does. True at the target reached.
bool runToTarget(Station& station) {
    RestartSequence& sequence = station.restartSequence();
    for (int step = 0; step < 50; ++step) {
        const RestartPhase phase = sequence.advance(kBlockBudget);
        if (phase == RestartPhase::TargetReached) return true;
        if (sequence.held() && !station.press(ControlKey::Start)) return false;
        if (!sequence.active()) return false;
    }
    return sequence.phase() == RestartPhase::TargetReached;
}

bool finite(const std::array<double, kMaxAxes>& values) {
    for (double v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

void checkCollisions(const removal::ReentryCheck& check, const ProgramStore& store, int process,
                     std::string_view input) {
    require(check.resolution > 0.0 && check.tolerance == check.resolution / 2.0,
            "the tolerance is half the resolution", input);
    require(std::isfinite(check.removedVolume) && check.removedVolume >= 0.0,
            "the removed volume is finite", input);
    require(check.collisions.size() <= check.moves, "at most one collision per move", input);
    for (std::size_t i = 0; i < check.collisions.size(); ++i) {
        const removal::ReentryCollision& c = check.collisions[i];
        require(c.move < check.moves, "a collision names a checked move", input);
        require(i == 0 || c.move > check.collisions[i - 1].move,
                "collisions in the order of the moves, each move once", input);
        require(finite(c.position), "a collision's machine position is finite", input);
        require(std::isfinite(c.scene[0]) && std::isfinite(c.scene[1]) && std::isfinite(c.scene[2]),
                "a collision's scene point is finite", input);
        require(store.find(process, c.where.program) != nullptr,
                "a collision names a block of a stored program", input);
    }
}

bool sameCollisions(const removal::ReentryCheck& a, const removal::ReentryCheck& b) {
    if (a.checked != b.checked || a.moves != b.moves || a.collisions.size() != b.collisions.size())
        return false;
    for (std::size_t i = 0; i < a.collisions.size(); ++i)
        if (a.collisions[i].move != b.collisions[i].move ||
            a.collisions[i].position != b.collisions[i].position ||
            a.collisions[i].rapid != b.collisions[i].rapid)
            return false;
    return true;
}

}  // namespace

void fuzzReentry(std::string_view input) {
    const int process = static_cast<int>(input.size() % 2);
    std::string_view rest = input;
    MachineConfig config = demoCell();
    config.processes[static_cast<std::size_t>(process)].stock = std::string(take(rest, '\n'));
    const std::vector<double> numbers = numbersOf(take(rest, '\n'));
    Cell cell(std::move(config));
    const int slot = cell.slotOfProcess(process);
    Station& station = cell.station(slot);
    cell.store().put(process, 1, parsed(take(rest, '\f'), 1));
    cell.store().put(process, 99, parsed(rest, 99));
    const ProgramPtr main = cell.store().find(process, 1);
    if (main->blocks.empty()) return;

    std::array<double, kMaxAxes> at = station.interpreter().state().modal.machine;
    // A machine stands at finite positions ("nan" and "inf" are numbers to
    // strtod: those axes stay where they are).
    for (std::size_t i = 1; i < numbers.size() && i <= at.size(); ++i)
        if (std::isfinite(numbers[i])) at[i - 1] = numbers[i];
    station.interpreter().takeMachinePositions(at);
    RestartSelection selection;
    selection.process = process;
    selection.mainProgram = 1;
    const double index = numbers.empty() ? 0.0 : std::fabs(numbers[0]);
    selection.target = {1, static_cast<std::uint32_t>(
                               std::isfinite(index) ? std::fmod(index, main->blocks.size()) : 0)};
    DiagnosticList refused;
    if (!station.restartSequence().accept(selection, refused, kBlockBudget)) return;
    if (!runToTarget(station)) return;

    removal::RemovalSettings settings;
    settings.resolution = 2.0;  // coarse: the fuzzer's executions stay fast
    const auto before = station.interpreter().state().modal.machine;
    const auto check = removal::checkRestartReentry(station.restart(), station.interpreter(),
                                                    cell.store(), settings);
    require(check.has_value(), "the way back is checked at the target reached", input);
    for (const Diagnostic& d : check->diagnostics.items())
        require(!d.code.empty() && !d.message.empty(), "a diagnostic has code and message", input);
    if (check->checked) {
        checkCollisions(*check, cell.store(), process, input);
    } else {
        require(check->collisions.empty(), "an unchecked way back lists no collision", input);
        require(!check->diagnostics.empty(), "an unchecked way back says why", input);
    }
    require(station.restart().phase() == RestartPhase::TargetReached &&
                station.interpreter().state().modal.machine == before,
            "the check changes nothing of the station", input);
    const auto again = removal::checkRestartReentry(station.restart(), station.interpreter(),
                                                    cell.store(), settings);
    require(again && sameCollisions(*check, *again), "the check says the same when asked again",
            input);
}

}  // namespace mtc::fuzz
