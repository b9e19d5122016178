#include <algorithm>

#include "cnc_core/compiler/CompilerPass.h"
#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/ObjectWriter.h"
#include "cnc_core/language/Parser.h"

namespace mtc::core {

CompileContext::CompileContext(const CompilerOptions& options, std::vector<CompilerError>& errors)
    : options_(options), errors_(errors) {}

bool CompileContext::report(const CompileBlock& block, Severity severity, std::string code,
                            std::string message, std::vector<std::string> details) {
    if (stopped_) return false;
    CompilerError error;
    error.severity = severity;
    error.code = std::move(code);
    error.block = block.number >= 0 ? formatBlockNumber(block.number) : std::string();
    error.sourceLine = static_cast<int>(block.sourceLine);
    error.program = options_.programNumber;
    error.message = limitMessage(message);
    error.details = limitDetails(details);
    return submit(std::move(error));
}

bool CompileContext::reportAt(const BlockSequence& blocks, std::size_t index, Severity severity,
                              std::string code, std::string message,
                              std::vector<std::string> details) {
    if (stopped_) return false;
    const bool ok =
        report(blocks[index], severity, std::move(code), std::move(message), std::move(details));
    if (!errors_.empty() && blocks[index].intermediate)
        errors_.back().block = blockId(blocks, index);
    return ok;
}

bool CompileContext::reportGeneral(std::string code, std::string message,
                                   std::vector<std::string> details) {
    if (stopped_) return false;
    CompilerError error;
    error.code = std::move(code);
    error.generalNumber = ++generalCount_;
    error.program = options_.programNumber;
    error.message = limitMessage(message);
    error.details = limitDetails(details);
    return submit(std::move(error));
}

bool CompileContext::submit(CompilerError error) {
    if (stopped_) return false;
    error.message = limitMessage(error.message);
    error.details = limitDetails(error.details);
    if (error.severity == Severity::Warning) {
        if (warningCount_ >= options_.maxErrors) return true;  // further warnings dropped
        ++warningCount_;
        errors_.push_back(std::move(error));
        return true;
    }
    if (error.sourceLine > 0) errorLines_.insert(static_cast<std::uint32_t>(error.sourceLine));
    errors_.push_back(std::move(error));
    if (++errorCount_ >= options_.maxErrors) stopped_ = true;
    return !stopped_;
}

const ParsedSequence& CompileContext::parsed(const BlockSequence& blocks) {
    if (parsedValid_) return parsed_;
    std::string text;
    std::size_t size = 0;
    for (const CompileBlock& block : blocks)
        size += block.prefix.size() + block.text.size() + 2;
    text.reserve(size);
    parsed_.blockOf.clear();
    parsed_.parsedOf.assign(blocks.size(), -1);
    std::vector<std::uint32_t> lineOwner;  // parse line - 1 -> sequence index
    lineOwner.reserve(blocks.size());
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        if (blocks[i].programEnd) continue;
        if (!blocks[i].prefix.empty()) text += blocks[i].prefix;  // nearly always empty
        text += blocks[i].text;
        text += '\n';
        lineOwner.push_back(static_cast<std::uint32_t>(i));
    }
    parsed_.program =
        parseProgram(std::move(text), {options_.programNumber, options_.programName, {}});
    for (std::size_t b = 0; b < parsed_.program.blocks.size(); ++b) {
        const std::uint32_t line = parsed_.program.blocks[b].line;
        const std::uint32_t owner = line >= 1 && line <= lineOwner.size()
                                        ? lineOwner[line - 1]
                                        : static_cast<std::uint32_t>(blocks.size());
        parsed_.blockOf.push_back(owner);
        if (owner < blocks.size()) parsed_.parsedOf[owner] = static_cast<std::int32_t>(b);
    }
    parsed_.lineOwner = std::move(lineOwner);
    parsedValid_ = true;
    return parsed_;
}

std::string CompileContext::blockId(const BlockSequence& blocks, std::size_t index) {
    // the numbering of writeObjectText: back to the block that starts the run
    std::size_t first = index;
    while (first > 0 && continuesNumbering(blocks[first], blocks[first - 1].number))
        --first;
    const CompileBlock& owner = blocks[first];
    const int sub = owner.sourceSub + static_cast<int>(index - first);
    if (owner.number < 0) return std::string();
    return formatBlockNumber(owner.number) + ":" + formatFourDigits(sub);
}

}  // namespace mtc::core
