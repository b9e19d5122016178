#pragma once

#include <QString>
#include <QVector>
#include <vector>

#include "cnc_core/compensation/InsertedBlocks.h"
#include "cnc_core/compiler/CompilerTypes.h"
#include "cnc_core/language/Program.h"

namespace mtc::screens {

/// The runtime program as the runtime view lists it (seed 001, ch. 1): the
/// compiled program's blocks (the compiler's intermediate blocks with their
/// enhanced numbers N0053:0001), the blocks the control inserts while it runs
/// (tool compensation's corner elements) marked with an arrow after the block
/// they follow, and per listed line the source line it stems from.
struct RuntimeListing {
    QString text;                ///< one listed line per object line after the header
    QVector<int> sourceLine;     ///< per listed line: 1-based source line (0 = none)
    QVector<bool> inserted;      ///< per listed line: a block the control inserts (arrow)
    int intermediateBlocks = 0;  ///< blocks the compiler inserted
    int insertedBlocks = 0;      ///< blocks tool compensation inserts (arrow)
};

/// The marker in front of a block the control inserts.
inline const QString kIntermediateArrow = QString::fromUtf8("\u2192 ");

/// Builds the listing of `result` (identification and header lines left
/// out, as in the runtime program; continuation lines follow their block).
/// `runtime` is the program parsed from the object text (its block lines are
/// object lines); `inserted` the blocks the control inserts into it.
RuntimeListing buildRuntimeListing(const mtc::core::CompileResult& result,
                                   const mtc::core::Program* runtime = nullptr,
                                   const std::vector<mtc::core::InsertedBlock>& inserted = {});

/// The listing of a program that runs as written (no compilation needed):
/// its source lines with the blocks the control inserts.
RuntimeListing buildSourceListing(const mtc::core::Program& program,
                                  const std::vector<mtc::core::InsertedBlock>& inserted);

}  // namespace mtc::screens
