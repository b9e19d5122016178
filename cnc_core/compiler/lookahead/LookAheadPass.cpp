#include "cnc_core/compiler/lookahead/LookAheadPass.h"

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/language/Keywords.h"

namespace mtc::core::lookahead {
namespace {

/// True when `text` holds F, an axis letter and then no further name
/// character (an F<axis> word such as FX=...), letters without case.
bool mayHoldAxisFeed(std::string_view text) {
    const auto upper = [](char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c; };
    for (const char f : {'F', 'f'}) {  // memchr jumps to the candidates
        for (std::size_t i = text.find(f); i != std::string_view::npos && i + 1 < text.size();
             i = text.find(f, i + 1))
            if (isAxisLetter(upper(text[i + 1])) &&
                (i + 2 == text.size() || !isNameChar(upper(text[i + 2]))))
                return true;
    }
    return false;
}

/// False when no block text names a look-ahead keyword: the analysis acts
/// only on LA_ON/LA_OFF, the variables and F<axis> words, so without them it
/// neither reports nor rewrites anything.
bool mayHoldLookAhead(const BlockSequence& blocks) {
    const CaselessNeedles lookAheadWords{"LA_", "METB",    "VFBT",     "TRC",
                                         "ACD", "ACC_EFF", "TL_RADIUS"};
    for (const CompileBlock& b : blocks) {
        if (b.programEnd) continue;
        if (lookAheadWords.foundIn(b.text)) return true;
        if (mayHoldAxisFeed(b.text)) return true;
    }
    return false;
}

}  // namespace

LookAheadPass::LookAheadPass(LookAheadDefaults defaults, std::shared_ptr<LookAheadAnalysis> capture)
    : defaults_(std::move(defaults)), capture_(std::move(capture)) {}

std::vector<std::string> LookAheadPass::keywords() const {
    return {"LA_ON", "LA_OFF", "METB", "VFBT",     "BBTRC",   "TL_RADIUS",
            "TRC",   "ADTRC",  "ACD",  "ACD_COMP", "ACC_EFF", "F<axis>"};
}

void LookAheadPass::run(BlockSequence& blocks, CompileContext& context) const {
    if (!mayHoldLookAhead(blocks)) {  // the common program without look-ahead words
        if (capture_) *capture_ = LookAheadAnalysis();
        return;
    }
    LookAheadAnalysis analysis = analyzeLookAhead(blocks, context, defaults_);
    if (context.stopped()) return;
    emitLookAhead(blocks, analysis);
    context.invalidate();
    if (capture_) *capture_ = std::move(analysis);
}

}  // namespace mtc::core::lookahead
