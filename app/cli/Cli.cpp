#include "cli/Cli.h"

#include <cstdio>
#include <string>

#include "cli/CheckCommand.h"
#include "cli/CliOptions.h"
#include "cli/CliOutput.h"
#include "cli/CompileCommand.h"
#include "cli/MachineDataCommand.h"
#include "cli/RestartCommand.h"
#include "cli/RunCommand.h"
#include "cli/SetupDataCommand.h"
#include "cli/SimulateCommand.h"
#include "cli/VerifyRestartCommand.h"

namespace mtc::cli {

namespace {

constexpr const char* kVersion = "mtc200-cli " MTC_CLI_VERSION;  // the project version (CMake)

}  // namespace

int runCli(int argc, char** argv) {
    const ParsedCommandLine parsed = parseCommandLine(argc, argv);
    if (!parsed.ok()) return reportUsageError(parsed.error, parsed.options.json);
    const CliOptions& options = parsed.options;
    switch (options.command) {
        case Command::Help:
            std::fputs(helpText().c_str(), stdout);
            return 0;
        case Command::Version:
            std::printf("%s\n", kVersion);
            return 0;
        case Command::Check:
            return runCheckCommand(options);
        case Command::Run:
            return runRunCommand(options);
        case Command::Restart:
            return runRestartCommand(options);
        case Command::VerifyRestart:
            return runVerifyRestartCommand(options);
        case Command::MachineData:
            return runMachineDataCommand(options);
        case Command::Compile:
            return runCompileCommand(options);
        case Command::Tools:
            return runToolsCommand(options);
        case Command::Offsets:
            return runOffsetsCommand(options);
        case Command::Simulate:
            return runSimulateCommand(options);
        case Command::None:
            break;
    }
    return reportUsageError("no command given", options.json);
}

}  // namespace mtc::cli
