#pragma once

#include "cnc_core/compiler/CompilerPass.h"

namespace mtc::core {

/// Chamfers (CF) and roundings (RD) between two motion blocks (seed 001,
/// ch. 2): the first motion block ends at the new corner point, an
/// intermediate block (G1 chamfer, G2/G3 rounding) is inserted after the
/// block holding the instruction, the second motion block starts at the
/// other corner point. Checks the boundary conditions of the seed (motion
/// block found within 20 blocks, no illegal function in between, no
/// variables in the plane end points, lines and arcs in the plane) and
/// reduces a size that does not fit (warning with the applied value).
class ChamferRoundPass : public CompilerPass {
  public:
    std::string_view name() const override { return "chamfer-rounding"; }
    int order() const override { return 400; }
    std::vector<std::string> keywords() const override { return {"CF", "RD"}; }
    void run(BlockSequence& blocks, CompileContext& context) const override;
};

}  // namespace mtc::core
