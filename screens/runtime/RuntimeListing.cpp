#include "screens/runtime/RuntimeListing.h"

#include <QHash>
#include <QStringList>

namespace mtc::screens {
namespace {

/// Inserted block texts by the 1-based line of the block they follow.
QHash<int, QStringList> insertionsByLine(const mtc::core::Program& program,
                                         const std::vector<mtc::core::InsertedBlock>& inserted) {
    QHash<int, QStringList> byLine;
    for (const auto& block : inserted) {
        if (block.program != program.number || block.afterBlock >= program.blocks.size()) continue;
        const int line = static_cast<int>(program.blocks[block.afterBlock].line);
        byLine[line] << QString::fromStdString(block.text);
    }
    return byLine;
}

/// Appends the arrow lines of `texts` (the block number column left blank, as in the seed).
void appendInserted(RuntimeListing& listing, QStringList& out, const QStringList& texts,
                    int sourceLine) {
    for (const QString& text : texts) {
        out << kIntermediateArrow + QString(10, ' ') + text;
        listing.sourceLine.push_back(sourceLine);
        listing.inserted.push_back(true);
        ++listing.insertedBlocks;
    }
}

}  // namespace

RuntimeListing buildRuntimeListing(const mtc::core::CompileResult& result,
                                   const mtc::core::Program* runtime,
                                   const std::vector<mtc::core::InsertedBlock>& inserted) {
    using mtc::core::ObjectLineKind;
    RuntimeListing listing;
    const QHash<int, QStringList> byLine =
        runtime ? insertionsByLine(*runtime, inserted) : QHash<int, QStringList>();
    const QStringList lines = QString::fromStdString(result.objectText).split('\n');
    const int count = std::min(int(lines.size()), int(result.lineMap.size()));
    QStringList out;
    QStringList pending;  ///< inserted after the current block and its continuation lines
    int pendingSource = 0;
    for (int i = 0; i < count; ++i) {
        const auto& entry = result.lineMap[size_t(i)];
        if (entry.kind != ObjectLineKind::Continuation) {
            appendInserted(listing, out, pending, pendingSource);
            pending.clear();
        }
        if (entry.kind == ObjectLineKind::Identification || entry.kind == ObjectLineKind::Header)
            continue;
        if (entry.kind == ObjectLineKind::Block && entry.intermediate) ++listing.intermediateBlocks;
        out << QString("  ") + lines[i];
        listing.sourceLine.push_back(int(entry.sourceLine));
        listing.inserted.push_back(false);
        if (entry.kind == ObjectLineKind::Block && byLine.contains(i + 1)) {
            pending = byLine.value(i + 1);
            pendingSource = int(entry.sourceLine);
        }
    }
    appendInserted(listing, out, pending, pendingSource);
    listing.text = out.join('\n');
    return listing;
}

RuntimeListing buildSourceListing(const mtc::core::Program& program,
                                  const std::vector<mtc::core::InsertedBlock>& inserted) {
    RuntimeListing listing;
    const QHash<int, QStringList> byLine = insertionsByLine(program, inserted);
    const QStringList lines = QString::fromStdString(program.source.str()).split('\n');
    // A block's text ends where the next block starts (continuation lines).
    QVector<int> blockEnd(lines.size() + 2, 0);  ///< source line -> line after which arrows go
    for (std::size_t b = 0; b < program.blocks.size(); ++b) {
        const int line = static_cast<int>(program.blocks[b].line);
        int last = b + 1 < program.blocks.size() ? int(program.blocks[b + 1].line) - 1 : line;
        while (last > line && last <= lines.size() && lines[last - 1].trimmed().isEmpty())
            --last;
        if (line >= 1 && line < blockEnd.size()) blockEnd[line] = std::max(last, line);
    }
    QHash<int, QStringList> after;  ///< by the line the arrows follow
    for (auto it = byLine.begin(); it != byLine.end(); ++it)
        if (it.key() >= 1 && it.key() < blockEnd.size()) after[blockEnd[it.key()]] << it.value();
    QStringList out;
    for (int i = 0; i < lines.size(); ++i) {
        out << QString("  ") + lines[i];
        listing.sourceLine.push_back(i + 1);
        listing.inserted.push_back(false);
        if (after.contains(i + 1)) appendInserted(listing, out, after.value(i + 1), i + 1);
    }
    listing.text = out.join('\n');
    return listing;
}

}  // namespace mtc::screens
