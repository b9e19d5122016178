#pragma once

#include <memory>

#include "cnc_core/compiler/CompilerPass.h"
#include "cnc_core/compiler/lookahead/LookAheadAnalysis.h"

namespace mtc::core::lookahead {

/// The enhanced look-ahead function as a compiler pass (seed 001 ch. 6,
/// order 500): reads METB, VFBT, BBTRC, TL_RADIUS, TRC, ADTRC, ACC_EFF and
/// ACD_COMP, checks every LA_ON ... LA_OFF segment, plans its velocity
/// profile and writes the blocks with sub-blocks of reduced F.
class LookAheadPass : public CompilerPass {
  public:
    /// `capture`, when given, receives the analysis of the last run (the
    /// velocity profile for the plot; VelocityProfileExport.h).
    explicit LookAheadPass(LookAheadDefaults defaults = {},
                           std::shared_ptr<LookAheadAnalysis> capture = nullptr);

    std::string_view name() const override { return "look-ahead"; }
    int order() const override { return 500; }
    std::vector<std::string> keywords() const override;
    void run(BlockSequence& blocks, CompileContext& context) const override;

  private:
    LookAheadDefaults defaults_;
    std::shared_ptr<LookAheadAnalysis> capture_;
};

}  // namespace mtc::core::lookahead
