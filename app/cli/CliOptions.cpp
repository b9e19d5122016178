#include "cli/CliOptions.h"

#include <charconv>
#include <string_view>

#include "cnc_core/removal/PartModel.h"
#include "cnc_core/restart/RestartSelection.h"

namespace mtc::cli {

namespace {

using core::kMaxRuns;
using core::kMinRuns;

constexpr std::uint64_t kMaxBlocksLimit = 1'000'000'000'000ULL;
constexpr int kMaxProcess = 99;

Command commandFromName(std::string_view name) {
    if (name == "check") return Command::Check;
    if (name == "run") return Command::Run;
    if (name == "restart") return Command::Restart;
    if (name == "verify-restart") return Command::VerifyRestart;
    if (name == "compile") return Command::Compile;
    if (name == "md") return Command::MachineData;
    if (name == "tools") return Command::Tools;
    if (name == "offsets") return Command::Offsets;
    if (name == "simulate") return Command::Simulate;
    if (name == "help") return Command::Help;
    return Command::None;
}

/// Parses a decimal unsigned integer that must use every character.
bool parseUnsigned(std::string_view text, std::uint64_t& value) {
    if (text.empty() || text.front() == '+' || text.front() == '-') return false;
    auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

class CommandLineReader {
  public:
    CommandLineReader(int argc, const char* const* argv) : argc_(argc), argv_(argv) {}

    ParsedCommandLine read() {
        for (index_ = 1; index_ < argc_ && out_.error.empty(); ++index_) {
            std::string_view arg = argv_[index_];
            if (onlyPositional_ || arg.size() < 2 || arg.front() != '-') {
                positional(arg);
            } else if (arg == "--") {
                onlyPositional_ = true;
            } else {
                option(arg);
            }
        }
        if (out_.error.empty()) validateCombination();
        return std::move(out_);
    }

  private:
    void positional(std::string_view arg) {
        CliOptions& o = out_.options;
        if (o.command != Command::None) {
            o.arguments.emplace_back(arg);
            return;
        }
        o.commandName = std::string(arg);
        o.command = commandFromName(arg);
        if (o.command == Command::None) out_.error = "unknown command '" + o.commandName + "'";
    }

    /// The value of an option: after '=' or the next argument.
    bool optionValue(std::string_view name, std::string_view inlineValue, bool hasInline,
                     std::string& value) {
        if (hasInline) {
            value = std::string(inlineValue);
            return true;
        }
        if (index_ + 1 >= argc_) {
            out_.error = "option " + std::string(name) + " needs a value";
            return false;
        }
        value = argv_[++index_];
        return true;
    }

    /// An option whose value may not be empty: stores it in `target`, or
    /// sets `whenEmpty` as the error.
    void requiredValue(std::string_view name, std::string_view inlineValue, bool hasInline,
                       std::string& target, const char* whenEmpty) {
        std::string value;
        if (!optionValue(name, inlineValue, hasInline, value)) return;
        target = value;
        if (target.empty() && out_.error.empty()) out_.error = whenEmpty;
    }

    void option(std::string_view arg) {
        const auto equals = arg.find('=');
        const bool hasInline = equals != std::string_view::npos;
        const std::string_view name = hasInline ? arg.substr(0, equals) : arg;
        const std::string_view inlineValue = hasInline ? arg.substr(equals + 1) : "";
        CliOptions& o = out_.options;
        std::string value;
        if (name == "--json" || name == "--no-motion" || name == "--help" || name == "-h" ||
            name == "--version" || name == "--from-primary" || name == "--adjust" ||
            name == "--check-collisions") {
            if (hasInline) {
                out_.error = "option " + std::string(name) + " takes no value";
                return;
            }
            flag(name);
        } else if (name == "--machine") {
            requiredValue(name, inlineValue, hasInline, o.machineFile, "--machine needs a file");
        } else if (name == "--programs") {
            requiredValue(name, inlineValue, hasInline, o.programsDir,
                          "--programs needs a directory");
        } else if (name == "--process") {
            if (optionValue(name, inlineValue, hasInline, value)) processValue(value);
        } else if (name == "--max-blocks") {
            if (optionValue(name, inlineValue, hasInline, value)) maxBlocksValue(value);
        } else if (name == "--sample-ms") {
            if (optionValue(name, inlineValue, hasInline, value)) sampleMsValue(value);
        } else if (name == "--user-compiler") {
            if (optionValue(name, inlineValue, hasInline, value)) o.userCompilers.push_back(value);
            if (out_.error.empty() &&
                (value.size() < 3 || value[0] < '1' || value[0] > '4' || value[1] != '='))
                out_.error = "--user-compiler needs SLOT=COMMAND with slot 1..4";
        } else if (name == "-o" || name == "--output") {
            requiredValue(name, inlineValue, hasInline, o.outputPath, "-o needs a file");
        } else if (name == "--target") {
            requiredValue(name, inlineValue, hasInline, o.target, "--target needs a path");
            o.restartOption = true;
        } else if (name == "--runs") {
            if (optionValue(name, inlineValue, hasInline, value)) runsValue(value);
        } else if (name == "--stl") {
            requiredValue(name, inlineValue, hasInline, o.stlPath, "--stl needs a file");
            o.simulateOption = true;
        } else if (name == "--resolution") {
            if (optionValue(name, inlineValue, hasInline, value)) resolutionValue(value);
        } else if (name == "--max-passes") {
            if (optionValue(name, inlineValue, hasInline, value)) maxPassesValue(value);
        } else if (isMachineDataOption(name)) {
            if (optionValue(name, inlineValue, hasInline, value))
                out_.error = o.machineData.take(name, value);
        } else {
            out_.error = "unknown option '" + std::string(arg) + "'";
        }
    }

    void flag(std::string_view name) {
        CliOptions& o = out_.options;
        if (name == "--json") o.json = true;
        if (name == "--no-motion") o.noMotion = true;
        if (name == "--help" || name == "-h") helpRequested_ = true;
        if (name == "--version") versionRequested_ = true;
        if (name == "--from-primary") o.fromPrimary = o.restartOption = true;
        if (name == "--adjust") o.adjust = true;
        if (name == "--check-collisions") o.checkCollisions = true;
    }

    /// Number of runs (seed 000, 2.6): 1..65536.
    void runsValue(const std::string& value) {
        std::uint64_t number = 0;
        out_.options.restartOption = true;
        if (!parseUnsigned(value, number) || number < kMinRuns || number > kMaxRuns) {
            out_.error = "bad value '" + value + "' for --runs (the number of runs is 1.." +
                         std::to_string(kMaxRuns) + ")";
            return;
        }
        out_.options.runs = static_cast<std::uint32_t>(number);
    }

    /// Passes per target block of verify-restart: 1..65536 like the number of runs.
    void maxPassesValue(const std::string& value) {
        std::uint64_t number = 0;
        out_.options.verifyOption = true;
        if (!parseUnsigned(value, number) || number < kMinRuns || number > kMaxRuns) {
            out_.error = "bad value '" + value + "' for --max-passes (1.." +
                         std::to_string(kMaxRuns) + ", like the number of runs)";
            return;
        }
        out_.options.maxPasses = static_cast<std::uint32_t>(number);
    }

    /// Cell size of simulate (mm): a plain decimal number in the model's range.
    void resolutionValue(const std::string& value) {
        out_.options.resolutionGiven = true;
        double number = 0.0;
        const char* end = value.data() + value.size();
        const auto result = std::from_chars(value.data(), end, number);
        const std::string problem = core::removal::resolutionProblem(number);
        if (value.empty() || result.ec != std::errc() || result.ptr != end || !problem.empty()) {
            out_.error = "bad value '" + value + "' for --resolution (" +
                         (problem.empty() ? core::removal::resolutionProblem(-1.0) : problem) + ")";
            return;
        }
        out_.options.resolution = number;
    }

    void processValue(const std::string& value) {
        std::uint64_t number = 0;
        if (!parseUnsigned(value, number) || number > kMaxProcess) {
            out_.error = "bad value '" + value + "' for --process (a process number 0.." +
                         std::to_string(kMaxProcess) + ")";
            return;
        }
        out_.options.process = static_cast<int>(number);
        out_.options.processGiven = true;
    }

    void maxBlocksValue(const std::string& value) {
        std::uint64_t number = 0;
        if (!parseUnsigned(value, number) || number == 0 || number > kMaxBlocksLimit) {
            out_.error = "bad value '" + value +
                         "' for --max-blocks (a whole number of blocks, 1.." +
                         std::to_string(kMaxBlocksLimit) + ")";
            return;
        }
        out_.options.maxBlocks = number;
    }

    void sampleMsValue(const std::string& value) {
        std::uint64_t number = 0;
        if (!parseUnsigned(value, number) || number == 0 || number > kMaxSampleMs) {
            out_.error = "bad value '" + value +
                         "' for --sample-ms (milliseconds of simulated time, 1.." +
                         std::to_string(kMaxSampleMs) + ")";
            return;
        }
        out_.options.sampleMs = static_cast<std::uint32_t>(number);
    }

    void validateCombination() {
        CliOptions& o = out_.options;
        if (versionRequested_) o.command = Command::Version;
        if (helpRequested_) o.command = Command::Help;
        if (o.command == Command::None) {
            out_.error = "no command given";
        } else if ((o.noMotion || o.sampleMs > 0) && o.command != Command::Run &&
                   o.command != Command::Help && o.command != Command::Version) {
            out_.error = "options --no-motion and --sample-ms belong to 'run'";
        } else if ((o.command == Command::Check || o.command == Command::Run ||
                    o.command == Command::Simulate) &&
                   o.arguments.empty()) {
            out_.error = "'" + o.commandName + "' needs a program (number or file)";
        } else if ((!o.outputPath.empty() || !o.userCompilers.empty()) &&
                   o.command != Command::Compile) {
            out_.error = "options -o and --user-compiler belong to 'compile'";
        } else if (o.command == Command::Run && o.arguments.size() > 1) {
            out_.error = "'run' takes exactly one program";
        } else if (o.restartOption && o.command != Command::Restart && o.command != Command::Help &&
                   o.command != Command::Version) {
            out_.error = "options --target, --runs and --from-primary belong to 'restart'";
        } else if (o.adjust && o.command != Command::Restart &&
                   o.command != Command::VerifyRestart && o.command != Command::Help &&
                   o.command != Command::Version) {
            out_.error = "option --adjust belongs to 'restart' and 'verify-restart'";
        } else if (o.verifyOption && o.command != Command::VerifyRestart &&
                   o.command != Command::Help && o.command != Command::Version) {
            out_.error = "option --max-passes belongs to 'verify-restart'";
        } else if (o.checkCollisions && o.command != Command::Restart &&
                   o.command != Command::Help && o.command != Command::Version) {
            out_.error = "option --check-collisions belongs to 'restart'";
        } else if (o.simulateOption && o.command != Command::Simulate &&
                   o.command != Command::Help && o.command != Command::Version) {
            out_.error = "options --stl and --resolution belong to 'simulate'";
        } else if (o.resolutionGiven && o.command != Command::Simulate &&
                   !(o.command == Command::Restart && o.checkCollisions) &&
                   o.command != Command::Help && o.command != Command::Version) {
            out_.error =
                "options --stl and --resolution belong to 'simulate' (--resolution also to "
                "'restart --check-collisions')";
        } else if (o.command == Command::Simulate && o.arguments.size() != 1) {
            out_.error = "'simulate' takes exactly one program";
        } else if (o.command == Command::VerifyRestart && o.arguments.size() != 1) {
            out_.error = "'verify-restart' takes exactly one program";
        } else if (o.machineData.given && o.command != Command::MachineData &&
                   o.command != Command::Tools && o.command != Command::Offsets &&
                   o.command != Command::Help && o.command != Command::Version &&
                   !((o.command == Command::Run || o.command == Command::Restart ||
                      o.command == Command::Simulate) &&
                     o.machineData.onlyDataFile())) {
            out_.error =
                "options --as, --password and --sub belong to 'md' (--data to md, tools, offsets, "
                "run, restart and simulate)";
        } else if (o.command == Command::Restart && o.arguments.size() != 1) {
            out_.error = "'restart' takes exactly one program";
        } else if (o.command == Command::Restart && o.target.empty()) {
            out_.error = "'restart' needs --target PATH";
        }
    }

    int argc_;
    const char* const* argv_;
    int index_ = 1;
    bool onlyPositional_ = false;
    bool helpRequested_ = false;
    bool versionRequested_ = false;
    ParsedCommandLine out_;
};

}  // namespace

ParsedCommandLine parseCommandLine(int argc, const char* const* argv) {
    return CommandLineReader(argc, argv).read();
}

std::string helpText() {
    return R"(usage: mtc200-cli [global options] COMMAND [arguments]

Headless MTC200 simulator (contract: docs/CLI-CONTRACT.md).

Commands available:
  check FILE|PROG...          parse and check programs; diagnostics only
  run   FILE|PROG [--no-motion] [--sample-ms N]
                              execute one program in simulated time, as
                              fast as possible (the panel's station, same
                              time, positions and signals); --no-motion
                              leaves the motion list out (without adaptive
                              feed control the machine then does not move
                              and the time is the programmed one);
                              --sample-ms N also samples time, block,
                              position and feed every N ms of simulated
                              time (1..3600000)
  restart FILE|PROG --target PATH [--runs K] [--from-primary] [--adjust]
          [--check-collisions [--resolution MM]]
                              NC program restart: the computing process up to
                              the target block (PATH: N<number> or L<line>
                              references, optionally P<program>:, joined by
                              '>' where a jump or call is followed); K runs
                              (1..65536); start at the last primary block;
                              --adjust goes on with ADJUST, manual mode,
                              automatic, REPOS and the re-entry;
                              --check-collisions checks the ADJUST/REPOS
                              moves against the part cut up to the target
                              (at --resolution MM, default 0.2)
  verify-restart FILE|PROG [--adjust] [--max-passes K]
                              restart verifier: every arrival at every block
                              of the program tree (the first K passes of each,
                              default 16) as a restart target; the computing
                              process must compute the state of a normal run
                              there; --adjust: after ADJUST and REPOS the
                              cutting state must be the target's. Exit 0 when
                              every target is re-established, 1 with the
                              differences listed
  md get [PAGE] [--sub N]     machine data page PAGE of --process as a table
                              (without PAGE: the pages of the process);
                              --sub N shows only sub-page N (page 61)
  md set PAGE ELEMENT VALUE [--as nc|sps|gui] [--password PW] [--sub N]
                              write one element as NC program, SPS or the
                              operator (default gui; password-protected
                              elements need --password); --sub N for page 61
                              (1 = M(16), 2 = Q); the value is kept in the
                              data file
  tools get [T<n>]            the tool list of --process (every edge: radius,
                              lengths L1..L3 with wear, edge orientation,
                              corner and setting angle, name)
  tools set T<n> [E<m>] KEY=VALUE...
                              create or change edge E (default 1) of tool T;
                              keys radius radius_wear l1 l2 l3 l1_wear l2_wear
                              l3_wear orientation corner_angle setting_angle
                              name; 'tools set T<n> [E<m>] delete' removes it
  offsets get [G54..G59]      zero offsets of --process (columns = axis
                              definitions X Y Z U V W A B C)
  offsets set G5x COLUMN=VALUE...
                              change columns of one zero offset
                              (tool lists and zero offsets are kept beside
                              the machine data file: <data>.tools,
                              <data>.offsets; docs/TOOL-DATA.md)
  compile FILE|PROG [-o OUT.NCO] [--user-compiler SLOT=COMMAND]...
                              NC compiler (macros, MODF, CF/RD): writes the
                              object file (.NCO), or the error file (.ERR)
                              on errors (warnings: .NCO and .ERR); user
                              compilers 1, 2 run before it, 3, 4 after it
  simulate FILE|PROG [--stl OUT.stl] [--resolution MM]
                              material removal: cut the process's stock
                              (machine configuration) with the program's tool
                              path and tools; report the removed volume (mm3)
                              and write the finished part as binary STL
                              (not when the program has errors). MM: cell
                              size 0.01..10 (default 0.2); at most 2000000
                              cells (a finer grid is refused with the
                              coarsest resolution that fits)
  help                        this text

Global options:
  --machine FILE      machine configuration (default: built-in demo cell)
  --process N         process (station) of the cell (default 0)
  --programs DIR      program directory with NuxxYzzz.DAT files
                      (default: built-in demo programs)
  --json              print exactly one JSON document on stdout
  --max-blocks N      bound of a run in interpreted blocks (default 10000000)
  --version           print the version
  --data FILE         machine data file of md (default:
                      $XDG_STATE_HOME/mtc200/machine-data/<cell>.mdt, or
                      ~/.local/state/...; '-' keeps nothing); run and
                      restart load it first and save what they changed
                      (without --data they keep nothing); simulate reads
                      the tool list beside it

A program is a program number (looked up in the program directory for the
selected process) or a path to a source file (.DAT with %NPG header or a
plain file of blocks).

Exit codes: 0 success, 1 the program or run has errors (md: the machine data
refused the request), 2 usage or file error (md: also text in a number).
)";
}

}  // namespace mtc::cli
