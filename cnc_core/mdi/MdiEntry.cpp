#include "cnc_core/mdi/MdiEntry.h"

#include <cctype>
#include <memory>
#include <string_view>

#include "cnc_core/compiler/GlobalMacroFile.h"
#include "cnc_core/language/Keywords.h"
#include "cnc_core/language/Parser.h"

namespace mtc::core {

namespace {

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::string current;
    for (char c : text) {
        if (c == '\n') {
            lines.push_back(current);
            current.clear();
        } else if (c != '\r') {
            current += c;
        }
    }
    if (!current.empty()) lines.push_back(current);
    return lines;
}

/// True when the line holds something to execute (not blank, not a comment).
bool hasBlock(const std::string& line) {
    for (char c : line) {
        if (c == ';') return false;
        if (c != ' ' && c != '\t') return true;
    }
    return false;
}

/// A line a program file's header begins or ends with ('%' first).
bool isFileHeaderLine(const std::string& line) {
    const std::size_t first = line.find_first_not_of(" \t");
    return first != std::string::npos && line[first] == '%';
}

SourceLocation lineLocation(std::size_t index) {
    SourceLocation where;
    where.line = static_cast<int>(index + 1);
    return where;
}

/// Expands every line; refused lines become diagnostics (all of them are
/// reported, not only the first) and are marked in the result.
std::vector<bool> expandLines(MdiEntry& entry, const std::vector<MacroDefinition>& globals) {
    std::vector<bool> refused(entry.lines.size(), false);
    for (std::size_t i = 0; i < entry.lines.size(); ++i) {
        const std::string& line = entry.lines[i];
        std::string expanded;
        std::string problem;
        if (isFileHeaderLine(line)) {
            // The parser reads an MDI entry as blocks only (fileLayout off:
            // fuzz findings mdi ba78da4, 633c4f6), where '%' is a bad
            // character; this says what the line is.
            entry.diagnostics.error("MDI_HEADER_REFUSED", lineLocation(i),
                                    "a program file's header line (%...) is not an NC block; "
                                    "MDI takes blocks only",
                                    {mdiInputDetail(static_cast<int>(i) + 1, line)});
            refused[i] = true;
        } else if (line.size() > kMaxMdiLineLength) {
            entry.diagnostics.error(
                "MDI_TOO_LONG", lineLocation(i),
                "an MDI line has at most " + std::to_string(kMaxMdiLineLength) + " characters");
            refused[i] = true;
        } else if (!expandMdiLine(line, globals, expanded, problem)) {
            entry.diagnostics.error("MDI_KEYWORD_REFUSED", lineLocation(i), problem,
                                    {mdiInputDetail(static_cast<int>(i) + 1, line)});
            refused[i] = true;
        }
        entry.expanded.push_back(refused[i] ? line : std::move(expanded));
    }
    return refused;
}

bool anyBlock(const std::vector<std::string>& lines) {
    for (const std::string& line : lines)
        if (hasBlock(line)) return true;
    return false;
}

/// The expanded lines, refused ones left blank (the line numbers stay).
std::string parseText(const std::vector<std::string>& lines, const std::vector<bool>& refused) {
    std::string text;
    for (std::size_t i = 0; i < lines.size(); ++i)
        text += (refused[i] ? std::string() : lines[i]) + '\n';
    return text;
}

/// The compiler keyword of a word's text: "RD" of "RD3", "LA_ON" of "LA_ON".
std::string keywordOf(std::string_view text) {
    std::size_t end = 0;
    while (end < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_'))
        ++end;
    const std::string name(text.substr(0, end));
    if (lookupKeyword(name).keywordClass != KeywordClass::None) return name;
    std::size_t letters = 0;  // the keyword with its value attached ("CF2")
    while (letters < name.size() &&
           (std::isupper(static_cast<unsigned char>(name[letters])) || name[letters] == '_'))
        ++letters;
    return name.substr(0, letters);
}

/// Every word the parser marked as a compiler keyword (one expandMdiLine did
/// not see, e.g. "RD3") refuses the entry with its line.
void refuseCompilerWords(const Program& program, MdiEntry& entry) {
    for (std::size_t b = 0; b < program.blocks.size(); ++b) {
        const Block block = program.blocks[b];
        for (std::uint32_t w = block.firstWord; w < block.firstWord + block.wordCount; ++w) {
            const Word word = program.words[w];
            if (!(word.flags & kWordNeedsCompiler)) continue;
            SourceLocation where = lineLocation(block.line > 0 ? block.line - 1 : 0);
            where.column = word.column;
            const std::size_t line = static_cast<std::size_t>(where.line - 1);
            entry.diagnostics.error(
                "MDI_KEYWORD_REFUSED", where,
                "the compiler keyword " + keywordOf(program.text(word.text)) +
                    " is not allowed in MDI",
                {mdiInputDetail(where.line,
                                line < entry.lines.size() ? entry.lines[line] : std::string())});
        }
    }
}

}  // namespace

MdiEntry prepareMdiEntry(const std::string& input, const std::vector<MacroDefinition>& globals) {
    MdiEntry entry;
    entry.input = input;
    entry.lines = splitLines(input);
    if (!anyBlock(entry.lines)) {
        entry.diagnostics.error("MDI_EMPTY", lineLocation(0), "no NC block was entered");
        return entry;
    }
    if (entry.lines.size() > kMaxMdiLines) {
        entry.diagnostics.error(
            "MDI_TOO_LONG", lineLocation(kMaxMdiLines),
            "an MDI entry has at most " + std::to_string(kMaxMdiLines) + " lines");
        return entry;
    }
    const std::vector<bool> refused = expandLines(entry, globals);
    ParseOptions options;
    options.name = kMdiProgramName;
    options.fileLayout = false;  // "%NPG" typed in MDI is no program header
    // One expanded line per input line: the parser's lines are the input's.
    auto program =
        std::make_shared<Program>(parseProgram(parseText(entry.expanded, refused), options));
    for (Diagnostic d : program->diagnostics.items()) {
        if (d.where.line > 0 && static_cast<std::size_t>(d.where.line) <= entry.lines.size())
            d.details.push_back(mdiInputDetail(d.where.line, entry.lines[d.where.line - 1]));
        entry.diagnostics.add(std::move(d));
    }
    if (program->usesCompilerKeywords) refuseCompilerWords(*program, entry);
    if (!entry.diagnostics.hasErrors()) entry.program = std::move(program);
    return entry;
}

std::string mdiRefusal(const ProcessControl& control) {
    if (control.mode() != OperatingMode::Mdi)
        return alarmText("ALARM_MDI_NOT_MDI_MODE",
                         "MDI refused: select MDI mode first (now %1 mode)", control.language(),
                         {modeName(control.mode())});
    if (control.programActive())
        return alarmText("ALARM_MDI_PROGRAM_ACTIVE",
                         "MDI refused: a program is active (Control reset first)",
                         control.language());
    return {};
}

std::string mdiInputDetail(int line, const std::string& text) {
    return "MDI input line " + std::to_string(line) + ": " + text;
}

std::string formatMdiDiagnostic(const Diagnostic& d, Language language) {
    const bool german = language == Language::German;
    std::string text = "MDI";
    if (d.where.line > 0) text += (german ? " Zeile " : " line ") + std::to_string(d.where.line);
    text += ": " + severityWord(d, language) + " [" + d.code + "]";
    if (!d.where.block.empty()) text += " " + d.where.block;
    text += ": " + messageLine(d, language);
    for (const auto& detail : d.details)
        text += "\n    " + detail;
    return text;
}

}  // namespace mtc::core
