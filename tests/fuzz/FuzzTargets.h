#pragma once

// The fuzz targets of the core's entry points (issue 22 §7): each one takes
// arbitrary bytes, feeds them to one reader or pass of cnc_core and checks
// the contracts that entry point promises (diagnostics, consistent indices,
// bounded output). A broken contract stops the process with a message: under
// libFuzzer that is a crash with its input saved; in ctest (ReplayTest.cpp,
// the normal compiler) a failed test.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace mtc::fuzz {

/// One entry point: `run` must return for every input (no crash, no hang).
struct FuzzTarget {
    const char* name;     ///< "parser", ... = tests/fuzz/regressions/<name>/
    const char* summary;  ///< what it drives
    void (*run)(std::string_view input);
};

/// Every target, in a fixed order.
const std::vector<FuzzTarget>& fuzzTargets();
/// The target called `name`, nullptr when there is none.
const FuzzTarget* findFuzzTarget(std::string_view name);

/// Stops the process (abort) with `what` and the start of `input` on stderr
/// when `condition` is false: the input broke a contract of the core.
void require(bool condition, const char* what, std::string_view input);

// The targets (targets/*.cpp).
void fuzzParser(std::string_view input);
void fuzzCompiler(std::string_view input);
void fuzzGne(std::string_view input);
void fuzzMachineConfig(std::string_view input);
void fuzzMachineDataFile(std::string_view input);
void fuzzTargetPath(std::string_view input);
void fuzzMdiEntry(std::string_view input);
void fuzzRemoval(std::string_view input);
void fuzzReentry(std::string_view input);

}  // namespace mtc::fuzz
