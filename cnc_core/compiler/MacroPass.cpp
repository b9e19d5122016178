#include "cnc_core/compiler/MacroPass.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/NameScan.h"
#include "cnc_core/language/Keywords.h"

namespace mtc::core {

namespace {

constexpr std::size_t kMaxMacroName = 20;         // seed 001 ch. 4
constexpr std::size_t kMaxGlobalMacroBody = 156;  // seed 001 ch. 4: 2 lines of 78

struct Definition {
    std::string name;
    std::string body;
    std::string problem;  // "" = well formed
};

/// "DEFINE name AS body" at the start of `text` (after a label); `found`
/// false when the block has no DEFINE.
Definition readDefinition(std::string_view text, bool& found, std::size_t& labelEnd) {
    Definition d;
    found = false;
    labelEnd = 0;
    if (text.find("DEFINE") == std::string_view::npos) return d;  // the common case
    std::size_t i = 0;
    while (i < text.size() && text[i] == ' ')
        ++i;
    labelEnd = 0;
    if (i < text.size() && text[i] == '.') {  // a label may stand before DEFINE
        while (i < text.size() && text[i] != ' ')
            ++i;
        labelEnd = i;
        while (i < text.size() && text[i] == ' ')
            ++i;
    }
    const std::size_t end = commentOffset(text);
    found = text.substr(i, 6) == "DEFINE" && (i + 6 >= end || text[i + 6] == ' ');
    if (!found) {
        forEachName(text, [&](std::size_t begin, std::size_t stop) {
            if (text.substr(begin, stop - begin) == "DEFINE") found = true;
        });
        if (found) d.problem = "DEFINE must be the first instruction of its block";
        return d;
    }
    i += 6;
    while (i < end && text[i] == ' ')
        ++i;
    const std::size_t nameBegin = i;
    while (i < end && text[i] != ' ')
        ++i;
    d.name = std::string(text.substr(nameBegin, i - nameBegin));
    while (i < end && text[i] == ' ')
        ++i;
    if (text.substr(i, 2) != "AS" || (i + 2 < end && text[i + 2] != ' ')) {
        d.problem = "macro definition: DEFINE <name> AS <instructions>";
        return d;
    }
    i += 2;
    std::string_view body = text.substr(i, end - i);
    while (!body.empty() && body.front() == ' ')
        body.remove_prefix(1);
    while (!body.empty() && body.back() == ' ')
        body.remove_suffix(1);
    d.body = std::string(body);
    if (d.body.empty()) d.problem = "the macro has no instructions after AS";
    return d;
}

/// What stays of a DEFINE block: its label and its comment. Built in a new
/// string: `text` must stay valid while both parts are read (a label of 16
/// or more characters would otherwise free the block text it is cut from).
std::string labelAndComment(std::string_view text, std::size_t labelEnd) {
    std::string kept(text.substr(0, labelEnd));
    const std::size_t comment = commentOffset(text);
    if (comment < text.size()) {
        if (!kept.empty()) kept += ' ';
        kept += text.substr(comment);
    }
    return kept;
}

/// "" or the problem when a macro defined before names `name` in its
/// instructions: defining `name` now would nest it (a single expansion
/// would leave the word in the object program; issue 22 §6).
std::string usedByEarlierMacro(const std::string& name, const MacroTable& table) {
    const MacroTable only{{name, std::string()}};
    for (const auto& [other, body] : table)
        if (other != name && !findMacroUse(body, only).empty())
            return "macros must not be nested (" + other + " uses " + name +
                   ", which is defined after it)";
    return std::string();
}

/// A macro name in a block text: [begin, end) and the macro's instructions.
struct MacroUse {
    std::size_t begin, end;  // no initialisers: an array of them is left as it is
    const std::string* body;
};

/// Writes `text` with its `count` macro uses expanded to `out`, which has
/// room for all of it.
void writeExpansion(const std::string& text, const MacroUse* uses, std::size_t count, char* out) {
    const char* const data = text.data();
    std::size_t copied = 0;
    for (std::size_t u = 0; u < count; ++u) {
        out = std::copy(data + copied, data + uses[u].begin, out);
        out = std::copy(uses[u].body->begin(), uses[u].body->end(), out);
        copied = uses[u].end;
    }
    std::copy(data + copied, data + text.size(), out);
}

/// Appends `text` with every macro use expanded to `out` (not `text`).
void appendExpansion(const std::string& text, const MacroMatcher& macros, std::string& out) {
    std::size_t copied = 0;
    const std::string_view view(text);
    forEachNameStartingWith(view, macros.firstLetters(), [&](std::size_t begin, std::size_t end) {
        const std::string* body = macros.find(view.substr(begin, end - begin));
        if (!body) return;
        out.append(text, copied, begin - copied);
        out += *body;
        copied = end;
    });
    out.append(text, copied, std::string::npos);
}

}  // namespace

std::string checkMacroName(std::string_view name) {
    if (name.empty() || !isLetter(name[0])) return "a macro name starts with a letter";
    for (char c : name)
        if (!isNameChar(c)) return "a macro name has only A-Z, 0-9 and '_'";
    if (name.size() > kMaxMacroName) return "a macro name has at most 20 characters";
    if (lookupKeyword(name).keywordClass != KeywordClass::None)
        return "the keyword " + std::string(name) + " cannot be redefined";
    return std::string();
}

std::string findMacroUse(std::string_view text, const MacroTable& table) {
    std::string found;
    forEachName(text, [&](std::size_t begin, std::size_t end) {
        if (found.empty() && table.count(std::string(text.substr(begin, end - begin))))
            found = std::string(text.substr(begin, end - begin));
    });
    return found;
}

MacroMatcher::MacroMatcher(const MacroTable& table) : table_(table) {
    for (const auto& entry : table) {
        const std::string& name = entry.first;
        if (name.empty() || !isLetter(name[0])) continue;  // can never match a visited name
        firstLetters_ |= 1u << (name[0] - 'A');
        shortest_ = std::min(shortest_, name.size());
        longest_ = std::max(longest_, name.size());
        entries_.emplace_back(name, &entry.second);
    }
    if (entries_.size() > kCompared) entries_.clear();  // the hash table is quicker then
}

const std::string* MacroMatcher::findInTable(std::string_view name) const {
    const auto it = table_.find(std::string(name));
    return it == table_.end() ? nullptr : &it->second;
}

bool expandMacros(const std::string& text, const MacroTable& table, std::string& out) {
    return expandMacros(text, MacroMatcher(table), out);
}

bool expandMacros(const std::string& text, const MacroMatcher& macros, std::string& out) {
    if (!macros.canMatch()) return false;
    // the uses first (a block has a few), then the result written into a
    // buffer on the stack and assigned to `out` at once (which may be
    // `text`); a block with more uses or a longer result is appended use by
    // use into a string of its own
    constexpr std::size_t kUses = 16;
    constexpr std::size_t kStackText = 512;
    MacroUse uses[kUses];
    std::size_t count = 0, size = text.size();
    bool fits = true;
    const std::string_view view(text);
    forEachNameStartingWith(view, macros.firstLetters(), [&](std::size_t begin, std::size_t end) {
        const std::string* body = macros.find(view.substr(begin, end - begin));
        if (!body) return;
        if (count == kUses) {
            fits = false;
            return;
        }
        uses[count++] = {begin, end, body};
        size += body->size() - (end - begin);
    });
    if (count == 0) return false;
    if (fits && size <= kStackText) {
        char buffer[kStackText];
        writeExpansion(text, uses, count, buffer);
        out.assign(buffer, size);
        return true;
    }
    std::string expanded;
    appendExpansion(text, macros, expanded);
    out = std::move(expanded);
    return true;
}

void MacroPass::run(BlockSequence& blocks, CompileContext& context) const {
    MacroTable table;
    for (const MacroDefinition& global : context.options().globalMacros) {
        std::string problem = checkMacroName(global.name);
        if (problem.empty() && global.body.size() > kMaxGlobalMacroBody)
            problem = "the instructions have more than 156 characters";
        if (problem.empty() && !findMacroUse(global.body, table).empty())
            problem = "macros must not be nested";
        if (problem.empty() && global.body.empty()) problem = "the macro has no instructions";
        if (!problem.empty()) {
            if (!context.reportGeneral("COMPILER_BAD_GLOBAL_MACRO",
                                       "Global macro " + global.name.substr(0, 20) + " invalid.",
                                       {problem, "Measure: correct it in the NC options."}))
                return;
            continue;
        }
        table[global.name] = global.body;
    }
    std::optional<MacroMatcher> macros{std::in_place, table};  // made anew when the table changes
    for (std::size_t i = 0; i < blocks.size() && !context.stopped(); ++i) {
        CompileBlock& block = blocks[i];
        if (block.programEnd) continue;
        bool isDefine = false;
        std::size_t labelEnd = 0;
        Definition d = readDefinition(block.text, isDefine, labelEnd);
        if (!isDefine) {
            if (!table.empty() && expandMacros(block.text, *macros, block.text))
                block.changed = true;  // written in place (the block keeps its buffer)
            continue;
        }
        if (d.problem.empty()) d.problem = checkMacroName(d.name);
        if (d.problem.empty()) {
            MacroTable withSelf = table;
            withSelf[d.name] = d.body;
            const std::string nested = findMacroUse(d.body, withSelf);
            if (!nested.empty()) d.problem = "macros must not be nested (" + nested + ")";
        }
        if (d.problem.empty()) d.problem = usedByEarlierMacro(d.name, table);
        if (!d.problem.empty()) {
            if (!context.report(block, Severity::Error, "COMPILER_BAD_MACRO",
                                "Invalid macro definition.",
                                {d.problem,
                                 "Syntax: DEFINE <name> AS <instructions>; nothing "
                                 "may follow the instructions in the block."}))
                return;
            continue;
        }
        if (table.count(d.name) &&
            !context.report(block, Severity::Warning, "COMPILER_MACRO_REDEFINED",
                            "Macro " + d.name + " redefined.",
                            {"From this block on, " + d.name + " stands for: " + d.body}))
            return;
        table[d.name] = d.body;
        macros.emplace(table);
        block.text = labelAndComment(block.text, labelEnd);
        block.changed = true;
    }
}

}  // namespace mtc::core
