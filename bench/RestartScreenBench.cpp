// Response of the restart screen's search pointer (seed 000, 2.3-2.6) on a
// 1,000,000-block program: every key must answer within 16 ms (one frame).
// Cursor, page, End, Search string (hit near the end and no hit at all),
// "restart from last primary block" (first use builds the primary index),
// and Enter with its warning checks. The GUI adds only the view's repaint of
// one page (tests/gui/test_restart_screen.cpp measures the real widgets).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <string>

#include "cnc_core/language/Parser.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/restart/SearchPointer.h"

namespace {

using namespace mtc::core;

constexpr int kBlocks = 1'000'000;

/// A machining-like program: moves with feeds, a comment on every tenth
/// block, a primary block every 1000 blocks, a G91 section near the start,
/// a subroutine after M30 and PROGRAMMENDE.
std::string generateRestartProgram(int blocks) {
    std::string text;
    text.reserve(static_cast<std::size_t>(blocks) * 36);
    char line[128];
    for (int i = 0; i < blocks - 4; ++i) {
        const char* primary = i % 1000 == 0 ? ": " : "";
        const int n = std::snprintf(line, sizeof line, "N%04d %sG1 X%.3f Y%d F%d%s\n", i % 10000,
                                    primary, (i % 500) * 0.25, i % 77, 800 + (i % 4) * 100,
                                    i % 10 == 0 ? " ;contour pass" : "");
        text.append(line, static_cast<std::size_t>(n));
        if (i == 20) text += "N0021 G91 X1\nN0022 G90\n";
    }
    text += "N9996 M30\nN9997 .EDGE G1 Z-1 ;find me\nN9998 RTS\nN9999 PROGRAMMENDE\n";
    return text;
}

struct Cell {
    ProgramStore store;
    Cell() {
        ParseOptions options;
        options.programNumber = 1;
        store.put(
            0, 1,
            std::make_shared<Program>(parseProgram(generateRestartProgram(kBlocks), options)));
    }
};

Cell& cell() {
    static Cell shared;  // parsed once for all benchmarks of this file
    return shared;
}

SearchPointer freshPointer() {
    SearchPointer pointer(cell().store, 0);
    pointer.begin(1);
    return pointer;
}

void BM_RestartCursorDown(benchmark::State& state) {
    SearchPointer pointer = freshPointer();
    for (auto _ : state) {
        pointer.down();
        benchmark::DoNotOptimize(pointer.current().cursor);
    }
}
BENCHMARK(BM_RestartCursorDown);

void BM_RestartPageDown(benchmark::State& state) {
    SearchPointer pointer = freshPointer();
    for (auto _ : state) {
        pointer.pageDown(30);
        if (pointer.current().cursor + 30 >= kBlocks) pointer.home();
        benchmark::DoNotOptimize(pointer.current().cursor);
    }
}
BENCHMARK(BM_RestartPageDown);

void BM_RestartEndHome(benchmark::State& state) {
    SearchPointer pointer = freshPointer();
    for (auto _ : state) {
        pointer.end();
        benchmark::DoNotOptimize(pointer.current().cursor);
        pointer.home();
    }
}
BENCHMARK(BM_RestartEndHome);

void BM_RestartSearchHitNearEnd(benchmark::State& state) {
    SearchPointer pointer = freshPointer();
    for (auto _ : state) {
        pointer.home();
        const bool found = pointer.search("find ME").ok;
        if (!found) state.SkipWithError("search text not found");
        benchmark::DoNotOptimize(pointer.current().cursor);
    }
}
BENCHMARK(BM_RestartSearchHitNearEnd)->Unit(benchmark::kMillisecond);

void BM_RestartSearchNoHit(benchmark::State& state) {
    SearchPointer pointer = freshPointer();
    for (auto _ : state) {
        pointer.home();
        benchmark::DoNotOptimize(pointer.search("Q9999").ok);
    }
}
BENCHMARK(BM_RestartSearchNoHit)->Unit(benchmark::kMillisecond);

void BM_RestartSearchCommonPrefix(benchmark::State& state) {
    // Every tenth block holds "contour pass": the filter sees many candidates.
    SearchPointer pointer = freshPointer();
    for (auto _ : state) {
        pointer.home();
        benchmark::DoNotOptimize(pointer.search("contour passes").ok);
    }
}
BENCHMARK(BM_RestartSearchCommonPrefix)->Unit(benchmark::kMillisecond);

void BM_RestartPrimaryFirstUse(benchmark::State& state) {
    for (auto _ : state) {
        SearchPointer pointer = freshPointer();  // new pointer: index not built yet
        pointer.end();
        benchmark::DoNotOptimize(pointer.setFromLastPrimary(true).ok);
    }
}
BENCHMARK(BM_RestartPrimaryFirstUse)->Unit(benchmark::kMillisecond);

void BM_RestartStartBlockLookup(benchmark::State& state) {
    SearchPointer pointer = freshPointer();
    pointer.end();
    pointer.setFromLastPrimary(true);
    for (auto _ : state) {
        pointer.up();
        benchmark::DoNotOptimize(pointer.startBlock());
    }
}
BENCHMARK(BM_RestartStartBlockLookup);

void BM_RestartAcceptAtEnd(benchmark::State& state) {
    SearchPointer pointer = freshPointer();
    pointer.end();
    for (auto _ : state)
        benchmark::DoNotOptimize(pointer.accept().ok);
}
BENCHMARK(BM_RestartAcceptAtEnd)->Unit(benchmark::kMillisecond);

void BM_RestartAcceptFromPrimaryAtEnd(benchmark::State& state) {
    // Start block near the end: the G91/G51 checks search back to the start.
    SearchPointer pointer = freshPointer();
    pointer.end();
    pointer.setFromLastPrimary(true);
    for (auto _ : state)
        benchmark::DoNotOptimize(pointer.accept().ok);
}
BENCHMARK(BM_RestartAcceptFromPrimaryAtEnd)->Unit(benchmark::kMillisecond);

}  // namespace
