// Golden-file tests of the interpreter: every tests/golden/interp/<name>.nc is
// run and its transcript (motions, aux functions, dwells, commands,
// diagnostics, run status, final state) compared with <name>.expected.
// Nothing is rewritten silently: set MTC_UPDATE_GOLDEN=1 to regenerate.
//
// Header comments of a golden program (all optional):
//   ; process: 1                   process of the demo cell (default 0)
//   ; program: 5                   number of the main program (default 1)
//   ; options: continue-after-error skip-blocks optional-stop no-motion
//   ; budget: 1000                 block budget of the run
//   ; event: 1:15                  event set before the run (repeatable)
//   ; expect-error: CODE           the run's errors, in order (repeatable)
//   ; expect-warning: CODE         the run's warnings, in order (repeatable)
//   ; tool: 1 radius 0.8 edge 5    sets tool T1 of the process's tool list
//                                  (radius, length, cutting edge orientation;
//                                  repeatable): cases the demo cell's tools lack
// A line ";== program N ==" starts another program of the same process
// (program 99 = label library, others for JSR/JMP); ";== cycle NAME ==" a cycle.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "InterpTestSupport.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;
namespace fs = std::filesystem;

struct GoldenCase {
    std::string name;
    fs::path source;
};

std::vector<GoldenCase> goldenCases() {
    std::vector<GoldenCase> cases;
    const fs::path dir = fs::path(MTC_TEST_DATA_DIR) / "interp";
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec))
        if (entry.path().extension() == ".nc")
            cases.push_back({entry.path().stem().string(), entry.path()});
    std::sort(cases.begin(), cases.end(),
              [](const auto& a, const auto& b) { return a.name < b.name; });
    return cases;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

struct GoldenProgram {
    int process = 0;
    int mainNumber = 1;
    std::uint64_t budget = kDefaultBlockBudget;
    std::vector<std::string> options, expectedErrors, expectedWarnings;
    std::vector<std::pair<int, int>> events;
    std::vector<ToolConfig> tools;
    std::vector<std::pair<int, std::string>> programs;        // number -> source
    std::vector<std::pair<std::string, std::string>> cycles;  // name -> source
};

std::string headerValue(const std::string& line, const std::string& key) {
    const std::string prefix = "; " + key + ":";
    if (line.rfind(prefix, 0) != 0) return {};
    std::string value = line.substr(prefix.size());
    while (!value.empty() && value.front() == ' ')
        value.erase(value.begin());
    while (!value.empty() && (value.back() == ' ' || value.back() == '\r'))
        value.pop_back();
    return value.empty() ? " " : value;
}

/// "1 radius 0.8 length 61.5 edge 5" (number first, then key/value pairs).
ToolConfig toolHeader(const std::string& value) {
    ToolConfig tool;
    std::istringstream words(value);
    words >> tool.number;
    tool.name = "golden" + std::to_string(tool.number);
    for (std::string key; words >> key;) {
        double v = 0.0;
        words >> v;
        if (key == "radius")
            tool.radius = v;
        else if (key == "length")
            tool.length = v;
        else if (key == "edge")
            tool.edgeOrientation = static_cast<int>(v);
        else
            ADD_FAILURE() << "unknown '; tool:' key " << key;
    }
    return tool;
}

/// The demo cell with the golden program's '; tool:' lines in its tool list.
MachineConfig cellFor(const GoldenProgram& g) {
    MachineConfig cell = demoCell();
    for (ProcessConfig& process : cell.processes) {
        if (process.index != g.process) continue;
        for (const ToolConfig& tool : g.tools) {
            auto same = std::find_if(process.tools.begin(), process.tools.end(),
                                     [&](const ToolConfig& t) { return t.number == tool.number; });
            if (same != process.tools.end())
                *same = tool;
            else
                process.tools.push_back(tool);
        }
    }
    return cell;
}

GoldenProgram readGolden(const std::string& text) {
    GoldenProgram g;
    std::istringstream in(text);
    std::string line, current;
    std::string sectionKind = "program";
    std::string sectionName;
    int sectionNumber = -1;
    auto flush = [&] {
        if (sectionKind == "cycle")
            g.cycles.emplace_back(sectionName, current);
        else
            g.programs.emplace_back(sectionNumber < 0 ? g.mainNumber : sectionNumber, current);
        current.clear();
    };
    while (std::getline(in, line)) {
        if (line.rfind(";== ", 0) == 0) {
            flush();
            std::istringstream words(line.substr(4));
            words >> sectionKind;
            if (sectionKind == "cycle")
                words >> sectionName;
            else
                words >> sectionNumber;
            continue;
        }
        std::string v;
        if (!(v = headerValue(line, "process")).empty()) g.process = std::atoi(v.c_str());
        if (!(v = headerValue(line, "program")).empty()) g.mainNumber = std::atoi(v.c_str());
        if (!(v = headerValue(line, "budget")).empty())
            g.budget = std::strtoull(v.c_str(), nullptr, 10);
        if (!(v = headerValue(line, "expect-error")).empty()) g.expectedErrors.push_back(v);
        if (!(v = headerValue(line, "expect-warning")).empty()) g.expectedWarnings.push_back(v);
        if (!(v = headerValue(line, "event")).empty())
            g.events.emplace_back(std::atoi(v.c_str()),
                                  std::atoi(v.substr(v.find(':') + 1).c_str()));
        if (!(v = headerValue(line, "tool")).empty()) g.tools.push_back(toolHeader(v));
        if (!(v = headerValue(line, "options")).empty()) {
            std::istringstream words(v);
            for (std::string w; words >> w;)
                g.options.push_back(w);
        }
        current += line + "\n";
    }
    flush();
    return g;
}

bool hasOption(const GoldenProgram& g, const std::string& option) {
    return std::find(g.options.begin(), g.options.end(), option) != g.options.end();
}

std::string runGolden(const GoldenProgram& g, DiagnosticList& diagnostics) {
    const MachineConfig cell = cellFor(g);
    Station station(cell, g.process);
    for (const auto& [number, source] : g.programs)
        station.add(source, number);
    for (const auto& [name, source] : g.cycles) {
        auto cycle = std::const_pointer_cast<Program>(parse(source, 0));
        cycle->isCycle = true;
        station.store.putCycle(name, cycle);
    }
    Interpreter& interp = *station.interpreter;
    interp.options().continueAfterError = hasOption(g, "continue-after-error");
    interp.options().skipBlocks = hasOption(g, "skip-blocks");
    interp.options().optionalStop = hasOption(g, "optional-stop");
    interp.options().output.motion = !hasOption(g, "no-motion");
    for (const auto& [process, event] : g.events)
        interp.events().set(process, event, true);
    std::string text;
    for (const auto& [number, source] : g.programs) {
        (void)source;
        const auto program = station.store.find(g.process, number);
        for (const auto& d : program->diagnostics.items())
            text += "parse " + diagnosticsText([&] {
                        DiagnosticList one;
                        one.add(d);
                        return one;
                    }());
    }
    interp.select(g.mainNumber);
    RunResult result = interp.run(g.budget);
    while (result.status == RunStatus::Stopped) {  // M00 / M01: continue like the Start key
        text += station.sink->text + diagnosticsText(result.diagnostics) +
                "stopped (M00/M01), start again\n";
        diagnostics.append(result.diagnostics);
        station.sink->text.clear();
        result = interp.run(g.budget);
    }
    diagnostics.append(result.diagnostics);
    text += station.sink->text + diagnosticsText(result.diagnostics);
    text += std::string("status ") + runStatusName(result.status) +
            " blocks=" + std::to_string(result.blocksInterpreted) + "\n";
    return text + stateText(interp);
}

class InterpGolden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(InterpGolden, TranscriptMatches) {
    const GoldenCase& c = GetParam();
    const GoldenProgram g = readGolden(readFile(c.source));
    DiagnosticList diagnostics;
    const std::string transcript = runGolden(g, diagnostics);

    std::vector<std::string> warnings;
    for (const auto& d : diagnostics.items())
        if (d.severity == Severity::Warning) warnings.push_back(d.code);
    EXPECT_EQ(errorCodes(diagnostics), g.expectedErrors)
        << "errors differ from '; expect-error:' lines";
    EXPECT_EQ(warnings, g.expectedWarnings) << "warnings differ from '; expect-warning:' lines";

    fs::path expectedPath = c.source;
    expectedPath.replace_extension(".expected");
    const char* update = std::getenv("MTC_UPDATE_GOLDEN");
    if (update && std::string(update) == "1") {
        std::ofstream(expectedPath, std::ios::binary) << transcript;
        return;
    }
    ASSERT_TRUE(fs::exists(expectedPath))
        << expectedPath << " is missing; run with MTC_UPDATE_GOLDEN=1 and review it\n"
        << transcript;
    EXPECT_EQ(transcript, readFile(expectedPath)) << "transcript of " << c.name << " changed";
}

INSTANTIATE_TEST_SUITE_P(Programs, InterpGolden, ::testing::ValuesIn(goldenCases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) {
                             std::string name = info.param.name;
                             for (char& ch : name)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return name;
                         });

TEST(InterpGoldenSet, HasPrograms) {
    EXPECT_GE(goldenCases().size(), 10u) << "tests/golden/interp/*.nc not found";
}

}  // namespace
