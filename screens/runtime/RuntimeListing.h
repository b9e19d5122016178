#pragma once

#include <QString>
#include <QVector>

#include "cnc_core/compiler/CompilerTypes.h"

namespace mtc::screens {

/// The runtime program as the runtime view lists it (seed 001, ch. 1): the
/// compiled program's blocks, the blocks the compiler inserted marked with
/// an arrow, and per listed line the source line it stems from.
struct RuntimeListing {
    QString text;                ///< one listed line per object line after the header
    QVector<int> sourceLine;     ///< per listed line: 1-based source line (0 = none)
    QVector<bool> intermediate;  ///< per listed line: an inserted block (arrow)
    int intermediateBlocks = 0;  ///< inserted blocks in the program
};

/// The marker in front of an inserted block.
inline const QString kIntermediateArrow = QString::fromUtf8("\u2192 ");

/// Builds the listing of `result` (identification and header lines left
/// out, as in the runtime program; continuation lines follow their block).
RuntimeListing buildRuntimeListing(const mtc::core::CompileResult& result);

}  // namespace mtc::screens
