// Search pointer under random operator input: random keys, windows,
// searches and number-of-runs texts on the test programs and the built-in
// demo programs of both processes. Nothing crashes, the cursor stays on a
// selectable block, and every selection Enter accepts is one the computing
// process's route check accepts too.
#include <gtest/gtest.h>

#include <random>

#include "SearchPointerTestSupport.h"
#include "cnc_core/program/ProgramLoader.h"
#include "cnc_core/restart/RestartRoute.h"
#include "resources/EmbeddedResources.h"

using namespace mtc::core;
using namespace mtc::core::testing;

namespace {

/// One random operator action.
void randomAction(SearchPointer& pointer, std::mt19937& random) {
    static const char* texts[] = {"", "0", "65537", "3", "x", "BSR", "rts", ";", "N00", "@"};
    const std::string text = texts[random() % 10];
    switch (random() % 14) {
        case 0:
            pointer.up();
            break;
        case 1:
            pointer.down();
            break;
        case 2:
            pointer.pageUp(random() % 40);
            break;
        case 3:
            pointer.pageDown(random() % 40);
            break;
        case 4:
            pointer.home();
            break;
        case 5:
            pointer.end();
            break;
        case 6:
            pointer.moveTo(random());
            break;
        case 7:
            pointer.planePlus();
            break;
        case 8:
            pointer.planeMinus();
            break;
        case 9:
            pointer.confirmEvent(random() % 2 == 0);
            break;
        case 10:
            pointer.confirmVariable(static_cast<double>(random() % 120) - 10.0);
            break;
        case 11:
            pointer.search(text);
            break;
        case 12:
            pointer.setRuns(text);
            break;
        default:
            pointer.setFromLastPrimary(random() % 2 == 0);
            break;
    }
}

/// Runs `steps` random actions on program `number` of `process`.
void exercise(const ProgramStore& store, int process, int number, unsigned seed, int steps) {
    SearchPointer pointer(store, process);
    ASSERT_TRUE(pointer.begin(number).ok) << "program " << number;
    std::mt19937 random(seed);
    for (int step = 0; step < steps; ++step) {
        randomAction(pointer, random);
        ASSERT_TRUE(pointer.active());
        ASSERT_LE(pointer.current().cursor, pointer.currentScan().lastSelectableBlock());
        ASSERT_LE(pointer.programLevels().size(), static_cast<std::size_t>(kMaxSearchLevels));
        ASSERT_GE(pointer.runs(), kMinRuns);
        ASSERT_LE(pointer.runs(), kMaxRuns);
        if (step % 7 != 0) continue;
        const AcceptResult accepted = pointer.accept();
        if (!accepted.ok) continue;
        RestartRoute route;
        DiagnosticList diagnostics;
        if (!planRestartRoute(accepted.selection, store, route, diagnostics)) {
            // The screen accepts a block of a subroutine body picked without
            // Plane+ or a target after a subroutine at the program start; the
            // NC refuses it (restart.md R-023).
            const std::string code = diagnostics.items().front().code;
            ASSERT_TRUE(code == "RESTART_TARGET_IN_SUBROUTINE" ||
                        code == "RESTART_START_BLOCK_NEEDED")
                << "seed " << seed << " step " << step << ": "
                << diagnostics.items().front().message;
            continue;
        }
        ASSERT_EQ(accepted.start.block.block, route.startBlock) << "seed " << seed;
    }
}

}  // namespace

TEST(SearchPointerFuzz, RandomInputOnTheTestPrograms) {
    SearchStore cell;
    for (unsigned seed = 1; seed <= 40; ++seed)
        for (int number : {5, 6, 7, 8, 99})
            exercise(cell.store, 0, number, seed, 400);
}

TEST(SearchPointerFuzz, RandomInputOnTheDemoPrograms) {
    ProgramStore store;
    ProgramLoader loader(store);
    std::vector<std::pair<std::string, std::string>> files;
    for (const auto& name : mtc::resources::list("programs/"))
        files.emplace_back(name, std::string(mtc::resources::find(name)));
    ASSERT_GT(loader.loadTexts(files), 0u);
    for (unsigned seed = 1; seed <= 40; ++seed)
        for (int process : {0, 1})
            exercise(store, process, 1, seed, 400);
}
