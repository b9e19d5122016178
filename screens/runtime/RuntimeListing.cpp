#include "screens/runtime/RuntimeListing.h"

#include <QStringList>

namespace mtc::screens {

RuntimeListing buildRuntimeListing(const mtc::core::CompileResult& result) {
    using mtc::core::ObjectLineKind;
    RuntimeListing listing;
    const QStringList lines = QString::fromStdString(result.objectText).split('\n');
    QStringList out;
    bool inInserted = false;
    for (int i = 0; i < lines.size() && i < int(result.lineMap.size()); ++i) {
        const auto& entry = result.lineMap[size_t(i)];
        if (entry.kind == ObjectLineKind::Identification || entry.kind == ObjectLineKind::Header)
            continue;
        if (entry.kind != ObjectLineKind::Continuation) inInserted = entry.intermediate;
        if (entry.kind == ObjectLineKind::Block && entry.intermediate) ++listing.intermediateBlocks;
        out << (inInserted ? kIntermediateArrow : QString("  ")) + lines[i];
        listing.sourceLine.push_back(int(entry.sourceLine));
        listing.intermediate.push_back(inInserted);
    }
    listing.text = out.join('\n');
    return listing;
}

}  // namespace mtc::screens
