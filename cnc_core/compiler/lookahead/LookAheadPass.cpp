#include "cnc_core/compiler/lookahead/LookAheadPass.h"

namespace mtc::core::lookahead {

LookAheadPass::LookAheadPass(LookAheadDefaults defaults, std::shared_ptr<LookAheadAnalysis> capture)
    : defaults_(std::move(defaults)), capture_(std::move(capture)) {}

std::vector<std::string> LookAheadPass::keywords() const {
    return {"LA_ON", "LA_OFF", "METB", "VFBT",     "BBTRC",   "TL_RADIUS",
            "TRC",   "ADTRC",  "ACD",  "ACD_COMP", "ACC_EFF", "F<axis>"};
}

void LookAheadPass::run(BlockSequence& blocks, CompileContext& context) const {
    LookAheadAnalysis analysis = analyzeLookAhead(blocks, context, defaults_);
    if (context.stopped()) return;
    emitLookAhead(blocks, analysis);
    context.invalidate();
    if (capture_) *capture_ = std::move(analysis);
}

}  // namespace mtc::core::lookahead
