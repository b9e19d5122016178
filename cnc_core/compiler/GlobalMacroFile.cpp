#include "cnc_core/compiler/GlobalMacroFile.h"

#include <fstream>
#include <sstream>

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/MacroPass.h"
#include "cnc_core/compiler/NameScan.h"
#include "cnc_core/compiler/SettingsText.h"
#include "cnc_core/language/Keywords.h"
#include "cnc_core/program/AtomicWrite.h"

namespace mtc::core {

namespace {

MacroTable tableOf(const std::vector<MacroDefinition>& macros, std::string_view skip) {
    MacroTable table;
    for (const MacroDefinition& macro : macros)
        if (macro.name != skip) table[macro.name] = macro.body;
    return table;
}

/// First compiler keyword used in `text` outside the comment and outside
/// free texts ("" = none); the names the macro pass looks at.
std::string compilerKeywordIn(std::string_view text) {
    std::string found;
    forEachName(text, [&](std::size_t begin, std::size_t end) {
        if (!found.empty()) return;
        const std::string_view name = text.substr(begin, end - begin);
        const KeywordClass kind = lookupKeyword(name).keywordClass;
        if (kind == KeywordClass::CompilerCommand || kind == KeywordClass::CompilerRestOfBlock)
            found = std::string(name);
    });
    return found;
}

/// Splits "DEFINE name AS body"; false when the line does not have that form.
bool splitDefinition(std::string_view line, MacroDefinition& macro) {
    line = trimmedSettingText(line);
    if (line.substr(0, 7) != "DEFINE ") return false;
    line = trimmedSettingText(line.substr(7));
    const std::size_t nameEnd = line.find(' ');
    if (nameEnd == std::string_view::npos) return false;
    macro.name = std::string(line.substr(0, nameEnd));
    line = trimmedSettingText(line.substr(nameEnd));
    if (line.substr(0, 2) != "AS" || (line.size() > 2 && line[2] != ' ')) return false;
    macro.body = std::string(trimmedSettingText(line.substr(2)));
    return true;
}

}  // namespace

std::string checkGlobalMacro(const MacroDefinition& candidate,
                             const std::vector<MacroDefinition>& others,
                             std::string_view replacing) {
    if (std::string problem = checkMacroName(candidate.name); !problem.empty()) return problem;
    for (const MacroDefinition& other : others)
        if (other.name == candidate.name && other.name != replacing)
            return "the macro " + candidate.name + " is already defined";
    if (trimmedSettingText(candidate.body).empty()) return "the macro has no instructions";
    if (candidate.body.size() > kMaxGlobalMacroBodyLength)
        return "the instructions have more than 156 characters";
    if (candidate.body.find_first_of("\n\r") != std::string::npos)
        return "the instructions must stand on one line";
    for (char c : candidate.body)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
            return "the instructions contain a control character";
    if (commentOffset(candidate.body) < candidate.body.size())
        return "nothing may follow the instructions (no comment)";
    if (std::string keyword = compilerKeywordIn(candidate.body); keyword == "DEFINE")
        return "a macro cannot define a macro";
    const MacroTable table = tableOf(others, replacing);
    if (std::string used = findMacroUse(candidate.body, table); !used.empty())
        return "macros must not be nested (uses " + used + ")";
    MacroTable self{{candidate.name, candidate.body}};
    for (const MacroDefinition& other : others) {
        if (other.name == replacing) continue;
        if (!findMacroUse(other.body, self).empty())
            return "macros must not be nested (" + other.name + " uses " + candidate.name + ")";
    }
    if (!findMacroUse(candidate.body, self).empty())
        return "macros must not be nested (uses itself)";
    return {};
}

MacroFileContents parseGlobalMacroFile(std::string_view text) {
    MacroFileContents contents;
    forEachSettingLine(text, [&contents](int lineNumber, std::string_view line) {
        MacroDefinition macro;
        if (!splitDefinition(line, macro)) {
            contents.problems.push_back({lineNumber, "expected DEFINE <name> AS <instructions>"});
            return;
        }
        if (std::string problem = checkGlobalMacro(macro, contents.macros); !problem.empty()) {
            contents.problems.push_back({lineNumber, macro.name.substr(0, 20) + ": " + problem});
            return;
        }
        contents.macros.push_back(std::move(macro));
    });
    return contents;
}

std::string formatGlobalMacroFile(const std::vector<MacroDefinition>& macros) {
    std::string text = "; global macros of the NC options (seed 001 ch. 4)\n";
    for (const MacroDefinition& macro : macros)
        text += "DEFINE " + macro.name + " AS " + macro.body + "\n";
    return text;
}

MacroFileContents readGlobalMacroFile(const std::string& directory) {
    const std::string path = directory + "/" + kGlobalMacroFileName;
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};  // a missing file: no global macros
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return {{}, {{0, "cannot read " + path}}};
    return parseGlobalMacroFile(text.str());
}

bool writeGlobalMacroFile(const std::string& directory, const std::vector<MacroDefinition>& macros,
                          std::string& error) {
    return writeFileAtomically(directory + "/" + kGlobalMacroFileName,
                               formatGlobalMacroFile(macros), error);
}

bool expandMdiLine(const std::string& line, const std::vector<MacroDefinition>& globals,
                   std::string& expanded, std::string& problem) {
    if (std::string keyword = compilerKeywordIn(line); !keyword.empty()) {
        problem = keyword == "DEFINE"
                      ? "macros cannot be defined in MDI (NC options)"
                      : "the compiler keyword " + keyword + " is not allowed in MDI";
        return false;
    }
    if (!expandMacros(line, tableOf(globals, {}), expanded)) expanded = line;
    if (std::string keyword = compilerKeywordIn(expanded); !keyword.empty()) {
        problem = "the compiler keyword " + keyword + " is not allowed in MDI";
        return false;
    }
    return true;
}

}  // namespace mtc::core
