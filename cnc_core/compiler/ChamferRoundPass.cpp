#include "cnc_core/compiler/ChamferRoundPass.h"

#include <algorithm>
#include <optional>

#include "cnc_core/compiler/ChamferRoundScan.h"
#include "cnc_core/compiler/CompilerText.h"

namespace mtc::core {

namespace {

constexpr int kMaxBlocksBetween = 20;  // seed 001 ch. 2

/// Changes to make to one block's text.
struct BlockEdit {
    std::optional<Point2> newStart, newEnd;
    bool removeCorner = false;
    int prependG = -1;
};

/// A corner to insert after block `at`.
struct Insertion {
    std::size_t at = 0;
    std::string text;
};

/// "N0053" for a source block, "N0053:0001" for an intermediate one.
std::string shortId(const BlockSequence& blocks, std::size_t index) {
    if (blocks[index].intermediate) return CompileContext::blockId(blocks, index);
    return blocks[index].number >= 0 ? formatBlockNumber(blocks[index].number)
                                     : "in line " + std::to_string(blocks[index].sourceLine);
}

const char* kindName(CornerKind kind) {
    return kind == CornerKind::Chamfer ? "CF" : "RD";
}

/// "X12.5 Y3" for a point of the plane, in programmed units.
std::string planeWords(const CompilerPlane& plane, bool diameter, const Point2& p) {
    std::string out;
    for (int k = 0; k < 2; ++k) {
        if (k) out += ' ';
        out += plane.axis[k] + formatCoordinate(p[k] / axisScale(plane.axis[k], diameter));
    }
    return out;
}

std::string centreWords(const CompilerPlane& plane, bool diameter, const Point2& c) {
    std::string out;
    for (int k = 0; k < 2; ++k) {
        if (k) out += ' ';
        out += plane.centre[k] + formatCoordinate(c[k] / axisScale(plane.axis[k], diameter));
    }
    return out;
}

/// The words of the inserted block.
std::string insertedText(const ScannedBlock& a, CornerKind kind, const CornerFit& fit) {
    const Point2 origin = a.absolute ? Point2::Zero() : fit.pointA;
    std::string text = kind == CornerKind::Chamfer ? "G1 " : (fit.ccw ? "G3 " : "G2 ");
    text += planeWords(a.plane, a.diameter, fit.pointB - origin);
    if (kind == CornerKind::Rounding)
        text += " " + centreWords(a.plane, a.diameter, fit.center - origin);
    return text;
}

/// Applies `edit` to the text of a motion block scanned as `s`.
std::string editedText(const std::string& text, const ScannedBlock& s, const BlockEdit& edit) {
    struct Span {
        std::size_t begin, end;
    };
    std::vector<Span> remove;
    std::string insert;
    const bool geometry = edit.newEnd || (edit.newStart && !s.absolute);
    if (geometry) {
        for (const ScannedWord& w : s.axes)
            if (w.name == s.plane.axis[0] || w.name == s.plane.axis[1])
                remove.push_back({w.begin, w.end});
        const Point2 start = edit.newStart.value_or(s.element.start);
        const Point2 end = edit.newEnd.value_or(s.element.end);
        insert = planeWords(s.plane, s.diameter, s.absolute ? end : Point2(end - start));
        if (s.element.arc && !s.absolute) {
            for (const ScannedWord& w : s.centres)
                remove.push_back({w.begin, w.end});
            insert += " " + centreWords(s.plane, s.diameter, s.element.center - start);
        }
    }
    if (edit.removeCorner) remove.push_back({s.cornerBegin, s.cornerEnd});
    std::sort(remove.begin(), remove.end(), [](Span x, Span y) { return x.begin < y.begin; });
    const std::size_t comment = commentOffset(text);
    std::size_t insertAt = remove.empty() || !geometry ? comment : remove.front().begin;
    std::string out;
    std::size_t copied = 0;
    for (const Span& span : remove) {
        if (span.begin < copied || span.end > text.size()) continue;
        out.append(text, copied, span.begin - copied);
        if (span.begin == insertAt && !insert.empty()) {
            out += ' ' + insert + ' ';
            insert.clear();
        }
        copied = span.end;
    }
    if (!insert.empty() && insertAt >= copied) {
        out.append(text, copied, insertAt - copied);
        copied = insertAt;
        out += ' ' + insert + ' ';
    }
    out.append(text, copied, std::string::npos);
    if (edit.prependG >= 0) out = "G" + std::to_string(edit.prependG) + " " + out;
    // one blank between words (the comment keeps its own spacing)
    std::string cleaned;
    const std::size_t newComment = commentOffset(out);
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (i < newComment && out[i] == ' ' && (cleaned.empty() || cleaned.back() == ' ')) continue;
        cleaned += out[i];
    }
    while (!cleaned.empty() && cleaned.back() == ' ')
        cleaned.pop_back();
    return cleaned;
}

class CornerJob {
  public:
    CornerJob(BlockSequence& blocks, CompileContext& context,
              const std::vector<ScannedBlock>& scanned)
        : blocks_(blocks),
          context_(context),
          scanned_(scanned),
          edits_(blocks.size()),
          minimum_(blocks.size(), 0.0) {}

    /// Handles the CF/RD of block i; false when the compile must stop.
    bool corner(std::size_t i);
    void apply();

  private:
    bool fail(std::size_t i, const char* code, const std::string& message,
              std::vector<std::string> details) {
        return context_.reportAt(blocks_, i, Severity::Error, code, message, std::move(details));
    }
    bool checkMotion(std::size_t i, std::size_t m, const char* which);

    BlockSequence& blocks_;
    CompileContext& context_;
    const std::vector<ScannedBlock>& scanned_;
    std::vector<BlockEdit> edits_;
    std::vector<double> minimum_;  // path length of a motion block already used by a corner
    std::vector<Insertion> insertions_;
};

bool CornerJob::checkMotion(std::size_t i, std::size_t m, const char* which) {
    const ScannedBlock& s = scanned_[m];
    const std::string id = shortId(blocks_, m);
    if (s.motionG != 1 && s.motionG != 2 && s.motionG != 3)
        return fail(i, "COMPILER_CFRD_NOT_CONTOUR", "CF/RD needs G1, G2 or G3 motion.",
                    {std::string("The ") + which + " motion block " + id +
                     " is a rapid traverse (G0)."}) &&
               false;
    if (s.outOfPlane)
        return fail(i, "COMPILER_CFRD_OUT_OF_PLANE", "CF/RD: motion outside the plane.",
                    {std::string("The ") + which + " motion block " + id +
                     " moves an axis outside the active plane G" + std::to_string(s.plane.code) +
                     "."}) &&
               false;
    if (s.planeVariable)
        return fail(i, "COMPILER_CFRD_VARIABLE", "CF/RD: end point given by a variable.",
                    {std::string("The ") + which + " motion block " + id +
                     " gives a plane coordinate by a variable; the compiler cannot compute it."}) &&
               false;
    if (!s.startKnown)
        return fail(i, "COMPILER_CFRD_START_UNKNOWN", "CF/RD: start point unknown.",
                    {std::string("The start point of the ") + which + " motion block " + id +
                     " is not known to the compiler: program both plane axes with constants "
                     "before it."}) &&
               false;
    if (!s.validElement)
        return fail(i, "COMPILER_CFRD_BAD_ELEMENT", "CF/RD: motion block unusable.",
                    {std::string("The ") + which + " motion block " + id + ": " + s.elementProblem +
                     "."}) &&
               false;
    return true;
}

bool CornerJob::corner(std::size_t i) {
    const ScannedBlock& c = scanned_[i];
    if (c.cornerCount > 1)
        return fail(i, "COMPILER_CFRD_TWICE", "Only one CF or RD per block.",
                    {"The block holds more than one chamfer/rounding instruction."});
    if (!c.sizeProblem.empty())
        return fail(i, "COMPILER_CFRD_VALUE",
                    std::string("Invalid ") + kindName(c.kind) + " value.", {c.sizeProblem});
    std::size_t a = i;
    if (!c.motion) {
        if (i == 0 || !scanned_[i - 1].motion)
            return fail(i, "COMPILER_CFRD_NO_PRECEDING_MOTION",
                        "CF/RD block without motion before.",
                        {"A CF/RD instruction in a block of its own must follow its first "
                         "motion block directly."});
        a = i - 1;
    }
    std::size_t b = i + 1;
    int between = 0;
    std::string illegal;
    for (; b < blocks_.size() && !blocks_[b].programEnd; ++b) {
        if (illegal.empty() && !scanned_[b].illegal.empty()) illegal = scanned_[b].illegal;
        if (scanned_[b].motion) break;
        if (++between > kMaxBlocksBetween) break;
    }
    if (b >= blocks_.size() || blocks_[b].programEnd || between > kMaxBlocksBetween)
        return fail(i, "COMPILER_CFRD_NO_TARGET", "No motion block found for CF/RD.",
                    {"The next motion block is missing, or more than 20 blocks without motion "
                     "follow the first motion block."});
    if (!illegal.empty())
        return fail(i, "COMPILER_CFRD_ILLEGAL", "CF/RD across an illegal function.",
                    {"Between the two motion blocks (up to " + shortId(blocks_, b) + ") " +
                     illegal + " is programmed; no chamfer or rounding is possible there."});
    if (!checkMotion(i, a, "first") || !checkMotion(i, b, "second")) return !context_.stopped();
    const ScannedBlock& sa = scanned_[a];
    const ScannedBlock& sb = scanned_[b];
    const CornerFit fit = fitCorner(c.kind, sa.element, minimum_[a], sb.element, c.size);
    edits_[i].removeCorner = true;
    if (fit.reduced &&
        !context_.reportAt(
            blocks_, i, Severity::Warning, "COMPILER_CFRD_REDUCED",
            std::string(kindName(c.kind)) + " reduced to " + formatCoordinate(fit.applied) + ".",
            {std::string("Programmed ") + kindName(c.kind) + " " + formatCoordinate(c.size) +
                 "; it does not fit between the motion blocks " + shortId(blocks_, a) + " and " +
                 shortId(blocks_, b) + ".",
             "Applied value: " + formatCoordinate(fit.applied) +
                 (fit.applied == 0.0 ? " (nothing inserted)." : ".")}))
        return false;
    if (fit.applied <= 0.0) return true;
    edits_[a].newEnd = fit.pointA;
    edits_[b].newStart = fit.pointB;
    minimum_[b] = sb.element.parameterOf(fit.pointB);
    const int insertedG = c.kind == CornerKind::Chamfer ? 1 : (fit.ccw ? 3 : 2);
    if (!sb.explicitMotionG && sb.motionG != insertedG) edits_[b].prependG = sb.motionG;
    insertions_.push_back({i, insertedText(sa, c.kind, fit)});
    return true;
}

void CornerJob::apply() {
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
        const BlockEdit& e = edits_[i];
        if (!e.newStart && !e.newEnd && !e.removeCorner && e.prependG < 0) continue;
        blocks_[i].text = editedText(blocks_[i].text, scanned_[i], e);
        blocks_[i].changed = true;
    }
    if (insertions_.empty()) return;
    BlockSequence out;
    out.reserve(blocks_.size() + insertions_.size());
    std::size_t next = 0;
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
        out.push_back(std::move(blocks_[i]));
        for (; next < insertions_.size() && insertions_[next].at == i; ++next) {
            CompileBlock block;
            block.number = out.back().number;
            block.sourceIndex = out.back().sourceIndex;
            block.sourceLine = out.back().sourceLine;
            block.intermediate = true;
            block.changed = true;
            block.text = insertions_[next].text;
            out.push_back(std::move(block));
        }
    }
    blocks_ = std::move(out);
}

}  // namespace

void ChamferRoundPass::run(BlockSequence& blocks, CompileContext& context) const {
    bool any = false;
    for (const CompileBlock& block : blocks)
        if (block.text.find("CF") != std::string::npos ||
            block.text.find("RD") != std::string::npos)
            any = true;
    if (!any) return;
    const std::vector<ScannedBlock> scanned =
        scanBlocks(blocks, context.parsed(blocks), context.options());
    CornerJob job(blocks, context, scanned);
    for (std::size_t i = 0; i < blocks.size(); ++i)
        if (scanned[i].cornerCount > 0 && !context.hasError(blocks[i]) && !job.corner(i)) return;
    if (context.stopped()) return;
    job.apply();
}

}  // namespace mtc::core
