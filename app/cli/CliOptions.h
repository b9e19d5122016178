#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cli/MachineDataOptions.h"

namespace mtc::cli {

/// The sub-command of mtc200-cli (CLI-CONTRACT.md).
enum class Command {
    None,
    Help,
    Version,
    Check,
    Run,
    Restart,
    VerifyRestart,
    Compile,
    MachineData,
    Tools,
    Offsets,
    Simulate
};

/// Default bound of a run: interpreted blocks before the run stops with a diagnostic.
inline constexpr std::uint64_t kDefaultMaxBlocks = 10'000'000;
/// Longest sampling interval of run --sample-ms (one hour).
inline constexpr std::uint32_t kMaxSampleMs = 3'600'000;

/// Everything the command line said, validated for syntax (not yet for
/// existence of files or processes).
struct CliOptions {
    Command command = Command::None;
    std::string commandName;             ///< as typed
    std::vector<std::string> arguments;  ///< positional arguments after the command
    std::string machineFile;             ///< empty = built-in demo cell
    std::string programsDir;             ///< empty = built-in demo programs
    int process = 0;
    bool processGiven = false;  ///< --process was on the command line
    bool json = false;
    std::uint64_t maxBlocks = kDefaultMaxBlocks;
    bool noMotion = false;
    std::uint32_t sampleMs =
        0;                   ///< run --sample-ms N: sample every N ms of simulated time (0 = no)
    std::string outputPath;  ///< compile: -o OUT.NCO
    std::vector<std::string> userCompilers;  ///< compile: --user-compiler SLOT=COMMAND
    // restart (CLI-CONTRACT.md):
    std::string target;            ///< --target PATH
    std::uint32_t runs = 1;        ///< --runs K, 1..65536
    bool fromPrimary = false;      ///< --from-primary
    bool adjust = false;           ///< --adjust (restart and verify-restart)
    bool checkCollisions = false;  ///< restart --check-collisions (D-021)
    bool restartOption = false;    ///< --target, --runs or --from-primary was given
    // verify-restart (CLI-CONTRACT.md "Extensions"):
    std::uint32_t maxPasses = 16;    ///< --max-passes K, 1..65536
    bool verifyOption = false;       ///< --max-passes was given
    MachineDataOptions machineData;  ///< md: --as, --password, --data, --sub
    // simulate (CLI-CONTRACT.md "Extensions", D-020):
    std::string stlPath;           ///< --stl OUT.stl ("" = no file)
    double resolution = 0.2;       ///< --resolution MM (simulate, restart --check-collisions)
    bool simulateOption = false;   ///< --stl was given
    bool resolutionGiven = false;  ///< --resolution was given
};

/// Result of reading argv: the options, or the usage error that stops the run
/// (exit code 2).
struct ParsedCommandLine {
    CliOptions options;
    std::string error;  ///< empty = the command line is well-formed
    bool ok() const { return error.empty(); }
};

/// Reads argv (argv[0] is skipped). Global options may stand before or after
/// the command; `--name=value` and `--name value` are both accepted; `--` ends
/// the options. Never throws: every problem is returned in `error`.
ParsedCommandLine parseCommandLine(int argc, const char* const* argv);

/// The help text printed by `mtc200-cli --help`.
std::string helpText();

}  // namespace mtc::cli
