#include "cli/CommandSetup.h"

#include <cmath>
#include <string>

#include "cli/MachineSetup.h"
#include "cnc_core/compiler/GlobalMacroFile.h"

namespace mtc::cli {

namespace {

bool isLabelJump(core::JumpKind kind) {
    switch (kind) {
        case core::JumpKind::BST:
        case core::JumpKind::RET:
        case core::JumpKind::RTS:
        case core::JumpKind::JSR:
        case core::JumpKind::JMP:
        case core::JumpKind::JEV:
            return false;
        default:
            return true;
    }
}

bool isProgramJump(core::JumpKind kind) {
    return kind == core::JumpKind::JSR || kind == core::JumpKind::JMP ||
           kind == core::JumpKind::JEV;
}

core::SourceLocation locationOf(const core::Program& program, std::size_t blockIndex,
                                const core::Word& word) {
    const core::Block& block = program.blocks[blockIndex];
    return {program.number, program.blockId(blockIndex), static_cast<int>(block.line), word.column};
}

bool inCycleMemory(const core::ProgramStore& store, std::string_view label) {
    for (const auto& [name, cycle] : store.cycles())
        if (cycle && cycle->findLabel(label) >= 0) return true;
    return false;
}

void checkLabel(const core::Program& program, const core::ProgramStore& store,
                const core::Program* library, std::size_t blockIndex, const core::Word& word,
                core::DiagnosticList& out) {
    const std::string_view label = program.text(word.text);
    if (label.empty()) return;  // a target in a variable or no label: checked at run time
    if (program.findLabel(label) >= 0) return;
    if (library != nullptr && library->findLabel(label) >= 0) return;
    if (inCycleMemory(store, label)) return;
    out.error("PROGRAM_LABEL_MISSING", locationOf(program, blockIndex, word),
              "label ." + std::string(label) + " not found in this program or in program 99",
              {"jump and call labels are searched in the running program, then in program 99"});
}

void checkCalledProgram(const core::Program& program, const core::ProgramStore& store, int process,
                        std::size_t blockIndex, const core::Word& word, core::DiagnosticList& out) {
    if (word.expr >= 0) return;  // program number in a variable: checked at run time
    const double number = word.number;
    if (number != std::floor(number) || number < 0 || number > 999) return;  // parser reports
    if (store.find(process, static_cast<int>(number)) != nullptr) return;
    out.error("PROGRAM_NOT_FOUND", locationOf(program, blockIndex, word),
              "program " + std::to_string(static_cast<int>(number)) + " of process " +
                  std::to_string(process) + " not found in the program memory");
}

}  // namespace

std::optional<CommandSetup> prepareCommand(const CliOptions& options,
                                           core::DiagnosticList& diagnostics) {
    std::optional<core::MachineConfig> machine = loadMachine(options.machineFile, diagnostics);
    if (!machine) return std::nullopt;
    if (options.processGiven && !checkProcessExists(*machine, options.process, diagnostics))
        return std::nullopt;
    CommandSetup setup{std::move(*machine), {}, {}};
    if (!options.programsDir.empty()) {  // first: the programs are parsed knowing the names
        core::MacroFileContents macros = core::readGlobalMacroFile(options.programsDir);
        for (const core::MacroFileProblem& problem : macros.problems)
            diagnostics.warning("GLOBAL_MACRO_REFUSED", {0, "", problem.line, 0},
                                std::string(core::kGlobalMacroFileName) + " line " +
                                    std::to_string(problem.line) + ": " + problem.message);
        setup.globalMacros = std::move(macros.macros);
        for (const core::MacroDefinition& macro : setup.globalMacros)
            setup.programs.macroNames.push_back(macro.name);
    }
    if (!loadProgramMemory(options.programsDir, setup.programs, diagnostics)) return std::nullopt;
    return setup;
}

core::DiagnosticList checkProgramReferences(const core::Program& program,
                                            const core::ProgramStore& store, int process) {
    core::DiagnosticList out;
    core::ProgramPtr library = store.library(process);
    const core::Program* libraryProgram = library.get() == &program ? nullptr : library.get();
    for (std::size_t b = 0; b < program.blocks.size(); ++b) {
        const core::Block& block = program.blocks[b];
        for (std::uint32_t w = block.firstWord; w < block.firstWord + block.wordCount; ++w) {
            if (w >= program.words.size()) break;
            const core::Word& word = program.words[w];
            if (word.kind != core::WordKind::Jump) continue;
            if (isLabelJump(word.jump)) checkLabel(program, store, libraryProgram, b, word, out);
            if (isProgramJump(word.jump)) checkCalledProgram(program, store, process, b, word, out);
        }
    }
    return out;
}

}  // namespace mtc::cli
