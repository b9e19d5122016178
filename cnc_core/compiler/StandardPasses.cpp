// The passes of the standard compiler. Modules that add a compiler function
// (look-ahead, graphical NC editor contours) add one line here.
#include "cnc_core/compiler/ChamferRoundPass.h"
#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/MacroPass.h"
#include "cnc_core/compiler/ModalFunctionPass.h"
#include "cnc_core/compiler/lookahead/LookAheadPass.h"
#include "cnc_core/contour/GnePass.h"

namespace mtc::core {

CompilerPassList standardCompilerPasses() {
    return {
        std::make_shared<MacroPass>(),
        std::make_shared<ModalFunctionPass>(),
        std::make_shared<gne::GnePass>(),
        std::make_shared<ChamferRoundPass>(),
        std::make_shared<lookahead::LookAheadPass>(),
    };
}

}  // namespace mtc::core
