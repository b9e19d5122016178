// GNE: the reader, the solver and the expansion of every contour, form and
// cycle. Every diagnostic has a message (and, after reading, a line); a
// document read without problems is written and read back to the same text;
// expanded NC blocks carry finite numbers only.
#include <string>

#include "../FuzzTargets.h"
#include "cnc_core/contour/GneExpansion.h"
#include "cnc_core/contour/GneText.h"

namespace mtc::fuzz {

using namespace mtc::core::gne;

void fuzzGne(std::string_view input) {
    const GneDocument doc = readGne(input);
    for (const GneDiagnostic& d : doc.diagnostics)
        require(!d.message.empty() && !d.code.empty(), "a GNE diagnostic says what", input);
    const GneExpansion expansion = expandGne(doc);
    for (const GneDiagnostic& d : expansion.diagnostics)
        require(d.line > 0 && !d.message.empty(), "an expansion diagnostic names its line", input);
    for (const ExpandedCall& call : expansion.calls)
        for (const std::string& block : call.blocks)
            require(
                block.find("nan") == std::string::npos && block.find("inf") == std::string::npos,
                "expanded blocks carry finite numbers", input);
    if (!doc.ok()) return;
    const std::string written = writeGne(doc);
    const GneDocument again = readGne(written);
    require(again.ok(), "written GNE text reads back without problems", input);
    require(writeGne(again) == written, "written GNE text reads back the same", input);
}

}  // namespace mtc::fuzz
