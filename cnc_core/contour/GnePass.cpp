#include "cnc_core/contour/GnePass.h"

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/contour/GneExpansion.h"
#include "cnc_core/contour/GneSchema.h"
#include "cnc_core/contour/GneText.h"

namespace mtc::core::gne {
namespace {

/// The sequence as text, one block per line (line i + 1 = blocks[i]).
std::string sequenceText(const BlockSequence& blocks) {
    std::string text;
    for (const CompileBlock& b : blocks) {
        if (!b.programEnd) text += b.text;
        text += '\n';
    }
    return text;
}

/// False when no block text can hold a GNE line: readGne() only acts on a
/// line whose first name is CONT, END_CONT, START, LINE, CW, CCW, RELIEF or
/// begins with WINDOW_, FORM_ or CYCLE_ (RD and CF only inside a contour).
bool mayHoldGne(const BlockSequence& blocks) {
    const CaselessNeedles gneWords{"CONT",   "START",   "LINE",  "CW",
                                   "RELIEF", "WINDOW_", "FORM_", "CYCLE_"};
    for (const CompileBlock& b : blocks)
        if (!b.programEnd && gneWords.foundIn(b.text)) return true;
    return false;
}

/// Reports `diagnostics` at their blocks; false once the compile must stop.
bool report(const std::vector<GneDiagnostic>& diagnostics, const BlockSequence& blocks,
            CompileContext& context) {
    for (const GneDiagnostic& d : diagnostics) {
        const std::size_t index = d.line >= 1 && d.line <= blocks.size() ? d.line - 1 : 0;
        std::vector<std::string> details;
        if (d.message.size() > 52) details.push_back(d.message);
        if (!context.reportAt(blocks, index, Severity::Error, d.code, d.message, details))
            return false;
    }
    return true;
}

void comment(CompileBlock& block) {
    block.text = ";" + block.text;
    block.changed = true;
}

}  // namespace

std::vector<std::string> GnePass::keywords() const {
    std::vector<std::string> names = {"CONT", "END_CONT", "START", "LINE", "CW", "CCW", "RELIEF"};
    for (const CallSpec& spec : callSpecs())
        names.push_back(spec.keyword);
    return names;
}

void GnePass::run(BlockSequence& blocks, CompileContext& context) const {
    if (!mayHoldGne(blocks)) return;  // nothing to read: the common program without GNE
    const GneDocument document = readGne(sequenceText(blocks));
    if (document.items.empty() && document.diagnostics.empty()) return;
    std::vector<bool> gne(blocks.size(), false);
    for (const GneItem& item : document.items) {
        const std::uint32_t first = item.isContour ? item.contour.line : item.call.line;
        std::uint32_t last = item.isContour ? item.contour.endLine : item.call.line;
        if (last < first) last = first;  // CONT without END_CONT
        for (std::uint32_t line = first; line <= last && line <= blocks.size(); ++line)
            gne[line - 1] = true;
    }
    // The GNE lines become comments even when something is wrong, so that
    // the later passes do not take a contour's RD or CF for their own.
    for (std::size_t i = 0; i < blocks.size(); ++i)
        if (gne[i]) comment(blocks[i]);
    context.invalidate();
    if (!report(document.diagnostics, blocks, context) || !document.ok()) return;
    const GneExpansion expansion = expandGne(document);
    if (!report(expansion.diagnostics, blocks, context) || !expansion.ok()) return;
    for (auto call = expansion.calls.rbegin(); call != expansion.calls.rend(); ++call) {
        const std::size_t at = call->line;  // insert after blocks[line - 1]
        const CompileBlock& owner = blocks[at - 1];
        std::vector<CompileBlock> inserted;
        for (const std::string& text : call->blocks) {
            CompileBlock b;
            b.number = owner.number;
            b.sourceIndex = owner.sourceIndex;
            b.sourceLine = owner.sourceLine;
            b.intermediate = true;
            b.changed = true;
            b.text = text;
            inserted.push_back(std::move(b));
        }
        blocks.insert(blocks.begin() + static_cast<std::ptrdiff_t>(at), inserted.begin(),
                      inserted.end());
    }
    context.invalidate();
}

}  // namespace mtc::core::gne
