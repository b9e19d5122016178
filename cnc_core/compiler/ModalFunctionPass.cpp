#include "cnc_core/compiler/ModalFunctionPass.h"

#include "cnc_core/compiler/CompilerText.h"

namespace mtc::core {

namespace {

constexpr std::size_t kMaxModalText = 80;  // seed 001 ch. 5

/// True when the parsed block moves an axis (has an axis word).
bool movesAxis(const Program& program, std::int32_t parsedIndex) {
    if (parsedIndex < 0) return false;
    const Block block = program.blocks[static_cast<std::size_t>(parsedIndex)];
    for (std::uint32_t w = block.firstWord; w < block.firstWord + block.wordCount; ++w)
        if (program.words.kindAt(w) == WordKind::Axis) return true;
    return false;
}

/// One MODF_ON(...) / MODF_OFF found in a block text.
struct ModalWord {
    bool on = false;
    std::size_t begin = 0, end = 0;  ///< the span to remove
    std::string argument;            ///< MODF_ON's text, trimmed
    std::string problem;             ///< "" = well formed
};

/// The MODF words of `text` (outside comment and free texts), in order.
std::vector<ModalWord> findModalWords(std::string_view text) {
    std::vector<ModalWord> found;
    const std::size_t stop = commentOffset(text);
    std::size_t i = 0;
    while (i < stop) {
        if (!isNameChar(text[i]) || (i > 0 && isNameChar(text[i - 1]))) {
            ++i;
            continue;
        }
        std::size_t end = i;
        while (end < stop && isNameChar(text[end]))
            ++end;
        const std::string_view name = text.substr(i, end - i);
        if (name != "MODF_ON" && name != "MODF_OFF") {
            i = end;
            continue;
        }
        ModalWord word{name == "MODF_ON", i, end, {}, {}};
        if (word.on) {
            std::size_t open = end;
            while (open < stop && text[open] == ' ')
                ++open;
            std::size_t close = open < stop && text[open] == '(' ? text.find(')', open) : open;
            if (open >= stop || text[open] != '(' || close == std::string_view::npos ||
                close >= stop) {
                word.problem = "MODF_ON needs its text in parentheses: MODF_ON(...)";
            } else {
                std::string_view argument = text.substr(open + 1, close - open - 1);
                while (!argument.empty() && argument.front() == ' ')
                    argument.remove_prefix(1);
                while (!argument.empty() && argument.back() == ' ')
                    argument.remove_suffix(1);
                word.argument = std::string(argument);
                word.end = close + 1;
                if (word.argument.size() > kMaxModalText)
                    word.problem = "the modal text has " + std::to_string(word.argument.size()) +
                                   " characters; at most 80 are allowed";
                else if (word.argument.find("MODF_") != std::string::npos)
                    word.problem = "a modal text must not contain MODF_ON or MODF_OFF";
                else if (word.argument.empty())
                    word.problem = "the modal text is empty";
            }
        }
        i = word.end > i ? word.end : end;  // before the move below
        found.push_back(std::move(word));
    }
    return found;
}

/// `text` without the spans of `words`, and `insert` before the comment.
std::string rewrite(std::string_view text, const std::vector<ModalWord>& modal,
                    const std::string& insert) {
    std::string out;
    std::size_t copied = 0;
    for (const ModalWord& w : modal) {
        out.append(text.substr(copied, w.begin - copied));
        copied = w.end;
    }
    out.append(text.substr(copied));
    const std::size_t comment = commentOffset(out);
    std::string words = out.substr(0, comment);
    std::string rest = out.substr(comment);
    while (!words.empty() && words.back() == ' ')
        words.pop_back();
    if (!insert.empty()) {
        if (!words.empty()) words += ' ';
        words += insert;
    }
    if (!rest.empty()) words += ' ' + rest;
    return words;
}

}  // namespace

void ModalFunctionPass::run(BlockSequence& blocks, CompileContext& context) const {
    bool any = false;
    for (const CompileBlock& block : blocks)
        any = any || block.text.find("MODF_") != std::string::npos;
    if (!any) return;
    const ParsedSequence& parsed = context.parsed(blocks);
    std::string active;
    for (std::size_t i = 0; i < blocks.size() && !context.stopped(); ++i) {
        CompileBlock& block = blocks[i];
        if (block.programEnd || context.hasError(block)) continue;
        std::vector<ModalWord> words;
        if (block.text.find("MODF_") != std::string::npos) words = findModalWords(block.text);
        bool offHere = false;
        for (const ModalWord& w : words) {
            if (!w.problem.empty()) {
                if (!context.report(block, Severity::Error, "COMPILER_BAD_MODAL_FUNCTION",
                                    "Invalid modal function.",
                                    {w.problem, "Syntax: MODF_ON(text) ... MODF_OFF"}))
                    return;
                continue;
            }
            active = w.on ? w.argument : std::string();
            offHere = offHere || !w.on;
        }
        const bool insert =
            !active.empty() && !offHere && movesAxis(parsed.program, parsed.parsedOf[i]);
        if (words.empty() && !insert) continue;
        block.text = rewrite(block.text, words, insert ? active : std::string());
        block.changed = true;
    }
}

}  // namespace mtc::core
