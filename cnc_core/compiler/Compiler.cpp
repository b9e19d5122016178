#include "cnc_core/compiler/Compiler.h"

#include <algorithm>
#include <climits>
#include <set>

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/MacroPass.h"
#include "cnc_core/compiler/ObjectWriter.h"
#include "cnc_core/compiler/SourceBlocks.h"
#include "cnc_core/language/Keywords.h"
#include "cnc_core/language/Parser.h"

namespace mtc::core {

namespace {

/// The keyword of a compiler command word ("CF", "MODF_ON", "F<axis>").
std::string keywordOf(std::string_view wordText) {
    std::size_t end = 0;
    while (end < wordText.size() && isNameChar(wordText[end]))
        ++end;
    std::string name(wordText.substr(0, end));
    const KeywordClass found = lookupKeyword(name).keywordClass;
    if (name.size() >= 2 && name[0] == 'F' && found == KeywordClass::AxisFeed) return "F<axis>";
    if (found != KeywordClass::None) return name;
    std::size_t letters = 0;  // "CF2": the keyword with its value attached
    while (letters < name.size() &&
           ((name[letters] >= 'A' && name[letters] <= 'Z') || name[letters] == '_'))
        ++letters;
    return name.substr(0, letters);
}

/// Block id of an object line for a message ("N0053", "N0053:0001", "").
std::string objectBlockId(const ObjectLine& line) {
    if (line.sourceNumber < 0) return std::string();
    std::string id = formatBlockNumber(line.sourceNumber);
    if (line.subNumber > 0) id += ":" + formatFourDigits(line.subNumber);
    return id;
}

CompilerError errorAtObjectLine(const ObjectText& object, int line,
                                const CompilerOptions& options) {
    CompilerError error;
    error.program = options.programNumber;
    if (line >= 1 && static_cast<std::size_t>(line) <= object.lineMap.size()) {
        const ObjectLine& entry = object.lineMap[static_cast<std::size_t>(line - 1)];
        error.block = objectBlockId(entry);
        error.sourceLine = static_cast<int>(entry.sourceLine);
    }
    return error;
}

/// An error of a parse of the source or the object program as a compiler
/// message (the parser's code; "Syntax: " before its message).
CompilerError syntaxError(const Diagnostic& d, CompilerError error) {
    error.code = d.code;
    error.message = "Syntax: " + d.message;
    error.details = {d.message};
    error.details.insert(error.details.end(), d.details.begin(), d.details.end());
    return error;
}

/// "N0053" of the block that holds source `line` (a continuation line
/// included), "" when no numbered block does (a comment line).
std::string blockIdAtLine(const Program& program, int line) {
    std::size_t low = 0, high = program.blocks.size();  // blocks are in line order
    while (low < high) {
        const std::size_t middle = low + (high - low) / 2;
        if (static_cast<int>(program.blocks[middle].line) <= line)
            low = middle + 1;
        else
            high = middle;
    }
    if (low == 0) return std::string();
    const Block block = program.blocks[low - 1];
    if (block.number < 0 || line >= static_cast<int>(block.line) + block.lineCount) return {};
    return formatBlockNumber(block.number);
}

/// Errors of the source parse: the rules of the source file (seed 001 ch.
/// 10: lines of at most 71 characters, blocks of at most 230 characters in
/// 4 lines) and syntax errors, for the blocks no pass has reported (a pass
/// says it in the compiler's words, e.g. a bad DEFINE). A pass may rewrite a
/// block so that the error is gone from the object program (a long line
/// wrapped anew), so these are taken from the source: `check` and `compile`
/// refuse the same programs. More than 10,000 lines is the general error of
/// the object program.
void reportSourceErrors(const Program& program, const std::set<int>& reported,
                        CompileContext& context) {
    for (const Diagnostic& d : program.diagnostics.items()) {
        if (d.severity != Severity::Error || d.code == "FILE_TOO_MANY_LINES") continue;
        if (reported.count(d.where.line)) continue;  // a pass said it in its own words
        CompilerError error;
        error.program = context.options().programNumber;
        error.block = d.where.block.empty() ? blockIdAtLine(program, d.where.line) : d.where.block;
        error.sourceLine = d.where.line;
        if (!context.submit(syntaxError(d, std::move(error)))) return;
    }
}

/// Source lines with an error so far (one error per block and cause).
std::set<int> linesWithErrors(const std::vector<CompilerError>& errors) {
    std::set<int> lines;
    for (const CompilerError& e : errors)
        if (e.severity == Severity::Error && e.sourceLine > 0) lines.insert(e.sourceLine);
    return lines;
}

/// Syntax of the object program `program` (the parse of `object`) and
/// compiler keywords left in it that no pass handles (seed 001 ch. 7:
/// keywords of functions this compiler lacks).
void reportObjectProblems(const Program& program, const ObjectText& object,
                          const std::set<std::string>& handled, const std::set<int>& reported,
                          CompileContext& context) {
    const CompilerOptions& options = context.options();
    for (const Diagnostic& d : program.diagnostics.items()) {
        if (d.severity != Severity::Error || d.code == "FILE_TOO_MANY_LINES") continue;  // A error
        CompilerError error = errorAtObjectLine(object, d.where.line, options);
        if (reported.count(error.sourceLine)) continue;  // a pass reported this block already
        if (!context.submit(syntaxError(d, std::move(error)))) return;
    }
    if (!program.usesCompilerKeywords) return;  // no word needs a compiler
    for (std::size_t b = 0; b < program.blocks.size(); ++b) {
        const Block block = program.blocks[b];
        for (std::uint32_t w = block.firstWord; w < block.firstWord + block.wordCount; ++w) {
            const Word word = program.words[w];
            if (!(word.flags & kWordNeedsCompiler)) continue;
            const std::string keyword = keywordOf(program.text(word.text));
            if (handled.count(keyword)) continue;
            CompilerError error = errorAtObjectLine(object, static_cast<int>(block.line), options);
            error.code = "COMPILER_KEYWORD_UNSUPPORTED";
            error.message = "Keyword " + keyword + " not supported.";
            error.details = {"This compiler has no function for the keyword " + keyword + ".",
                             "Measure: remove the keyword or use a compiler that has it."};
            if (!context.submit(std::move(error))) return;
        }
    }
}

/// reportObjectProblems of a parse of `object`, which borrows its text (no
/// copy of the whole object program) and gives it back.
void checkObject(ObjectText& object, const std::set<std::string>& handled,
                 const std::set<int>& reported, CompileContext& context) {
    const CompilerOptions& options = context.options();
    Program program =
        parseProgram(std::move(object.text), {options.programNumber, options.programName, {}});
    reportObjectProblems(program, object, handled, reported, context);
    object.text = std::move(program.source).take();
}

}  // namespace

char statusLetter(CompileStatus status) {
    switch (status) {
        case CompileStatus::NotNeeded:
            return ' ';
        case CompileStatus::NotCompiled:
            return 'N';
        case CompileStatus::Compiled:
            return 'C';
        case CompileStatus::Error:
            return 'E';
    }
    return ' ';
}

bool CompileResult::hasErrors() const {
    return std::any_of(errors.begin(), errors.end(),
                       [](const CompilerError& e) { return e.severity == Severity::Error; });
}

Compiler::Compiler() : Compiler(standardCompilerPasses()) {}

Compiler::Compiler(CompilerPassList passes) : passes_(std::move(passes)) {
    std::stable_sort(passes_.begin(), passes_.end(),
                     [](const auto& a, const auto& b) { return a->order() < b->order(); });
}

void Compiler::addPass(std::shared_ptr<const CompilerPass> pass) {
    passes_.push_back(std::move(pass));
    std::stable_sort(passes_.begin(), passes_.end(),
                     [](const auto& a, const auto& b) { return a->order() < b->order(); });
}

namespace {

/// The parse options of a program compiled with `options`: a block using
/// a global macro is no unknown word.
ParseOptions sourceParseOptions(const CompilerOptions& options) {
    ParseOptions parse{options.programNumber, options.programName, {}};
    for (const MacroDefinition& macro : options.globalMacros)
        parse.macroNames.push_back(macro.name);
    return parse;
}

}  // namespace

CompileResult Compiler::compile(std::string_view source, const CompilerOptions& options) const {
    return compile(parseProgram(std::string(source), sourceParseOptions(options)), options);
}

CompileResult Compiler::compile(const Program& program, const CompilerOptions& options) const {
    CompileResult result;
    CompileContext context(options, result.errors);
    SourceFrame frame;
    BlockSequence blocks = splitSourceBlocks(program, frame);
    result.identification = frame.identification;
    std::set<std::string> handled;
    for (const auto& pass : passes_) {
        for (const std::string& keyword : pass->keywords())
            handled.insert(keyword);
        if (context.stopped()) break;
        pass->run(blocks, context);
        context.invalidate();
    }
    if (!context.stopped()) {
        // A program parsed without the names of the global macros has their
        // uses as unknown words: its errors come from a parse that knows them.
        const bool parsedWithoutMacros =
            !options.globalMacros.empty() && program.diagnostics.hasErrors();
        const Program renamed = parsedWithoutMacros
                                    ? parseProgram(program.source, sourceParseOptions(options))
                                    : Program{};
        reportSourceErrors(parsedWithoutMacros ? renamed : program, linesWithErrors(result.errors),
                           context);
    }
    if (!context.stopped()) {
        ObjectText object = writeObjectText(frame, blocks, context);
        if (!context.stopped())
            checkObject(object, handled, linesWithErrors(result.errors), context);
        result.objectText = std::move(object.text);
        result.lineMap = std::move(object.lineMap);
        result.objectBlocks = object.blocks;
    }
    // the error window lists the messages in program order, general ones last
    std::stable_sort(result.errors.begin(), result.errors.end(),
                     [](const CompilerError& a, const CompilerError& b) {
                         const int la = a.sourceLine > 0 ? a.sourceLine : INT_MAX;
                         const int lb = b.sourceLine > 0 ? b.sourceLine : INT_MAX;
                         return la < lb;
                     });
    result.status = result.hasErrors() ? CompileStatus::Error : CompileStatus::Compiled;
    if (result.status == CompileStatus::Error) {
        result.objectText.clear();
        result.lineMap.clear();
    }
    return result;
}

}  // namespace mtc::core

namespace mtc::core {

bool needsCompilation(const Program& program, const CompilerOptions& options) {
    if (!options.compilerActive) return false;
    if (program.usesCompilerKeywords) return true;
    if (options.globalMacros.empty()) return false;
    MacroTable table;
    for (const MacroDefinition& macro : options.globalMacros)
        table[macro.name] = macro.body;
    for (std::size_t b = 0; b < program.blocks.size(); ++b)
        if (!findMacroUse(program.text(program.blocks[b].sourceText), table).empty()) return true;
    return false;
}

}  // namespace mtc::core
