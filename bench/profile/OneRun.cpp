// One measured run of an issue-21 benchmark path, for exact instruction
// counts: the Google Benchmark binary also runs the fixture's check runs
// and a varying number of iterations, which blur a callgrind profile.
//
//   valgrind --tool=callgrind --toggle-collect='*measured*'
//       build/release/bench/mtc_one_run null|nomotion|moves|mixed|parse [FILE]
//
// (one command line) counts only the measured call: one Interpreter::run of the 1,000,000-block
// moves program (motion to a NullSink, or motion off), one
// ComputingProcess::advance to the last block of the moves or the mixed
// program (as BM_RestartComputingProcess*), or one parseProgram of FILE.
// Each uses the fixture and settings of its Google Benchmark (D-030).
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

#include "bench/BenchPrograms.h"
#include "cnc_core/language/Parser.h"

namespace {

using namespace mtc::core;
using Fixture = mtc::bench::BenchProgramFixture;

constexpr int kBlocks = 1'000'000;

[[gnu::noinline]] std::uint64_t measuredInterpretation(Interpreter& interpreter) {
    interpreter.select(1);
    return interpreter.run().blocksInterpreted;
}

[[gnu::noinline]] std::uint64_t measuredComputingProcess(ComputingProcess& computing) {
    return computing.advance(kDefaultBlockBudget).blocksInterpreted;
}

[[gnu::noinline]] std::uint64_t measuredParse(std::string text) {
    return parseProgram(std::move(text)).blocks.size();
}

std::uint64_t interpretation(bool motion) {
    const Fixture f(kBlocks, {false, false});  // as bench/InterpBench.cpp
    NullSink sink;
    Interpreter interpreter(*f.cell.process(0), f.store, sink);
    interpreter.options().output.motion = motion;
    return measuredInterpretation(interpreter);
}

std::uint64_t computingProcess(bool mixed) {
    const Fixture f(kBlocks, {mixed, true});  // as bench/RestartBench.cpp
    mtc::bench::ComputingProcessRun run(f);
    DiagnosticList diagnostics;
    return run.begin(diagnostics) ? measuredComputingProcess(run.computing) : 0;
}

std::uint64_t parse(const char* file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return measuredParse(text.str());
}

}  // namespace

int main(int argc, char** argv) {
    const std::string_view path = argc > 1 ? argv[1] : "";
    std::uint64_t blocks = 0;
    if (path == "null" || path == "nomotion")
        blocks = interpretation(path == "null");
    else if (path == "moves" || path == "mixed")
        blocks = computingProcess(path == "mixed");
    else if (path == "parse" && argc > 2)
        blocks = parse(argv[2]);
    else {
        std::fprintf(stderr, "usage: mtc_one_run null|nomotion|moves|mixed|parse FILE\n");
        return 2;
    }
    std::printf("%s: %llu blocks\n", argv[1], static_cast<unsigned long long>(blocks));
    return blocks > 0 ? 0 : 1;
}
