#pragma once

#include "cnc_core/compiler/CompilerPass.h"

namespace mtc::core {

/// Modal function (seed 001, ch. 5): MODF_ON(text) activates `text` (at
/// most 80 characters); it is written into every following block with axis
/// motion, starting with the MODF_ON block itself when that one moves an
/// axis. MODF_OFF ends it; its own block no longer gets the text.
class ModalFunctionPass : public CompilerPass {
  public:
    std::string_view name() const override { return "modal-function"; }
    int order() const override { return 200; }
    std::vector<std::string> keywords() const override { return {"MODF_ON", "MODF_OFF"}; }
    void run(BlockSequence& blocks, CompileContext& context) const override;
};

}  // namespace mtc::core
