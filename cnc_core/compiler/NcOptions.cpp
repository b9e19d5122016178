#include "cnc_core/compiler/NcOptions.h"

#include <array>
#include <cctype>
#include <fstream>
#include <sstream>

#include "cnc_core/compiler/CommandLine.h"
#include "cnc_core/compiler/GlobalMacroFile.h"
#include "cnc_core/compiler/SettingsText.h"
#include "cnc_core/program/AtomicWrite.h"

namespace mtc::core {

namespace {

const std::array<const char*, kUserCompilerSlotCount> kSlotKeys = {
    "USER_COMPILER_1", "USER_COMPILER_2", "USER_COMPILER_3", "USER_COMPILER_4"};
constexpr const char* kCompilerActiveKey = "COMPILER_ACTIVE";

std::string upper(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

/// Slot 1..4 of `key`, 0 for compiler active, -1 for an unknown key.
int keyIndex(const std::string& key) {
    if (key == kCompilerActiveKey) return 0;
    for (int slot = 1; slot <= kUserCompilerSlotCount; ++slot)
        if (key == kSlotKeys[static_cast<std::size_t>(slot - 1)]) return slot;
    return -1;
}

/// Applies one `KEY = value` line; "" when taken, else the reason.
std::string applySetting(std::string_view line, NcOptions& options,
                         std::array<bool, kUserCompilerSlotCount + 1>& seen) {
    const std::size_t equals = line.find('=');
    if (equals == std::string_view::npos) return "expected KEY = value";
    const std::string key = upper(trimmedSettingText(line.substr(0, equals)));
    const std::string_view value = trimmedSettingText(line.substr(equals + 1));
    const int index = keyIndex(key);
    if (index < 0) return "unknown setting '" + key.substr(0, 30) + "'";
    if (seen[static_cast<std::size_t>(index)]) return key + " is given twice (the first is kept)";
    if (index == 0) {
        const std::string answer = upper(value);
        if (answer != "YES" && answer != "NO") return key + " must be YES or NO";
        options.compilerActive = answer == "YES";
    } else {
        if (std::string problem = checkUserCompilerCommand(value); !problem.empty())
            return key + ": " + problem;
        setUserCompilerCommand(options.userCompilers, index, std::string(value));
    }
    seen[static_cast<std::size_t>(index)] = true;
    return {};
}

}  // namespace

const std::string& userCompilerCommand(const UserCompilerSlots& slots, int slot) {
    static const std::string none;
    if (slot == 1 || slot == 2) return slots.before[static_cast<std::size_t>(slot - 1)];
    if (slot == 3 || slot == 4) return slots.after[static_cast<std::size_t>(slot - 3)];
    return none;
}

bool setUserCompilerCommand(UserCompilerSlots& slots, int slot, std::string command) {
    if (slot == 1 || slot == 2)
        slots.before[static_cast<std::size_t>(slot - 1)] = std::move(command);
    else if (slot == 3 || slot == 4)
        slots.after[static_cast<std::size_t>(slot - 3)] = std::move(command);
    else
        return false;
    return true;
}

std::string checkUserCompilerCommand(std::string_view command) {
    if (command.size() > kMaxUserCompilerCommandLength)
        return "the command has more than " + std::to_string(kMaxUserCompilerCommandLength) +
               " characters";
    for (char c : command)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            return "the command contains a control character or a line break";
    if (trimmedSettingText(command).size() != command.size())
        return "the command starts or ends with a blank";
    std::vector<std::string> words;
    std::string problem;
    if (!command.empty() && !splitCommandLine(command, words, problem)) return problem;
    return {};
}

bool parseGlobalMacroEntry(std::string_view line, const std::vector<MacroDefinition>& others,
                           std::string_view replacing, MacroDefinition& macro,
                           std::string& problem) {
    if (line.find_first_of("\n\r") != std::string_view::npos) {
        problem = "the entry must stand on one line";
        return false;
    }
    const MacroFileContents single = parseGlobalMacroFile(line);
    if (!single.problems.empty()) {
        problem = single.problems.front().message;
        return false;
    }
    if (single.macros.size() != 1) {
        problem = "expected DEFINE <name> AS <instructions>";
        return false;
    }
    macro = single.macros.front();
    problem = checkGlobalMacro(macro, others, replacing);
    if (!problem.empty()) problem = macro.name + ": " + problem;
    return problem.empty();
}

NcOptionsContents parseNcOptionsFile(std::string_view text) {
    NcOptionsContents contents;
    std::array<bool, kUserCompilerSlotCount + 1> seen{};
    forEachSettingLine(text, [&contents, &seen](int lineNumber, std::string_view line) {
        if (std::string problem = applySetting(line, contents.options, seen); !problem.empty())
            contents.problems.push_back({kNcOptionsFileName, lineNumber, problem});
    });
    return contents;
}

std::string formatNcOptionsFile(const NcOptions& options) {
    std::string text =
        "; NC options of the MTC200 panel (seed 001 ch. 7, 8); global macros: "
        "GLOBAL_MACROS.MAC\n";
    text +=
        std::string(kCompilerActiveKey) + " = " + (options.compilerActive ? "YES" : "NO") + "\n";
    for (int slot = 1; slot <= kUserCompilerSlotCount; ++slot)
        text += std::string(kSlotKeys[static_cast<std::size_t>(slot - 1)]) + " = " +
                userCompilerCommand(options.userCompilers, slot) + "\n";
    return text;
}

NcOptionsContents readNcOptions(const std::string& directory) {
    NcOptionsContents contents;
    const std::string path = directory + "/" + kNcOptionsFileName;
    if (std::ifstream in(path, std::ios::binary); in) {
        std::ostringstream text;
        text << in.rdbuf();
        if (in.bad())
            contents.problems.push_back({kNcOptionsFileName, 0, "cannot read " + path});
        else
            contents = parseNcOptionsFile(text.str());
    }
    const MacroFileContents macros = readGlobalMacroFile(directory);
    contents.options.globalMacros = macros.macros;
    for (const MacroFileProblem& problem : macros.problems)
        contents.problems.push_back({kGlobalMacroFileName, problem.line, problem.message});
    return contents;
}

bool writeNcOptionsFile(const std::string& directory, const NcOptions& options,
                        std::string& error) {
    return writeFileAtomically(directory + "/" + kNcOptionsFileName, formatNcOptionsFile(options),
                               error);
}

}  // namespace mtc::core
