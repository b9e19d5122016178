#pragma once

#include "cnc_core/compiler/CompilerPass.h"

namespace mtc::core::gne {

/// The graphical NC editor's instructions in the NC compiler (seed 001,
/// ch. 3 and 12; pass order 300): WINDOW_0x, CONT ... END_CONT and FORM_xx
/// become comment blocks (they only define geometry), every CYCLE_xx block
/// becomes a comment block followed by its NC blocks as intermediate blocks
/// (N0020:0001, ...). Any reading, solving or expansion error is reported at
/// its block and leaves the sequence unchanged.
class GnePass : public CompilerPass {
  public:
    std::string_view name() const override { return "gne"; }
    int order() const override { return 300; }
    std::vector<std::string> keywords() const override;
    void run(BlockSequence& blocks, CompileContext& context) const override;
};

}  // namespace mtc::core::gne
