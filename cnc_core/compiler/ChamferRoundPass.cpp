#include "cnc_core/compiler/ChamferRoundPass.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <string_view>

#include "cnc_core/compiler/ChamferRoundScan.h"
#include "cnc_core/compiler/CompilerText.h"

namespace mtc::core {

namespace {

constexpr int kMaxBlocksBetween = 20;  // seed 001 ch. 2

/// Changes to make to one block's text.
struct BlockEdit {
    std::optional<Point2> newStart, newEnd;
    bool consumed = false;  ///< the corners used up the whole element: its motion goes
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

/// Ticks (0.0001 steps) of coordinate k of `p` in programmed units.
long long planeTicks(const CompilerPlane& plane, bool diameter, const Point2& p, int k) {
    return coordinateTicks(p[k] / axisScale(plane.axis[k], diameter));
}

/// Appends "<nameA><a> <nameB><b>" ("X12.5 Y3", "I2 J-1.5"; numbers as
/// appendTicks writes them) with one append: the words are written back to
/// front into one buffer (names of at most 8 characters; longer ones are
/// appended piece by piece).
void appendWordPair(std::string& out, std::string_view nameA, long long a, std::string_view nameB,
                    long long b) {
    constexpr std::size_t kShortName = 8;
    if (nameA.size() > kShortName || nameB.size() > kShortName) {
        out += nameA;
        appendTicks(out, a);
        out += ' ';
        out += nameB;
        appendTicks(out, b);
        return;
    }
    char buffer[2 * (kShortName + kMaxTicksText) + 1];
    char* const end = buffer + sizeof buffer;
    char* first = writeTicksBefore(end, b);
    first -= nameB.size();
    nameB.copy(first, nameB.size());
    *--first = ' ';
    first = writeTicksBefore(first, a);
    first -= nameA.size();
    nameA.copy(first, nameA.size());
    out.append(first, static_cast<std::size_t>(end - first));
}

/// Appends "X12.5 Y3" for the point `to` of the plane in programmed units:
/// absolute (G90), or incremental from `from` (G91) as the difference of the
/// two points' rounded values, so that a chain of incremental blocks ends
/// exactly where the programmed one does (no drift from rounding).
void appendPlaneWords(std::string& out, const CompilerPlane& plane, bool diameter, bool absolute,
                      const Point2& from, const Point2& to) {
    long long ticks[2];
    for (int k = 0; k < 2; ++k) {
        const long long end = planeTicks(plane, diameter, to, k);
        ticks[k] = absolute ? end : end - planeTicks(plane, diameter, from, k);
    }
    appendWordPair(out, plane.axis[0], ticks[0], plane.axis[1], ticks[1]);
}

/// Appends "I2 J-1.5" for the circle centre `c`: absolute (G90) or relative
/// to the arc's start `from` (G91), in programmed units.
void appendCentreWords(std::string& out, const CompilerPlane& plane, bool diameter, bool absolute,
                       const Point2& from, const Point2& c) {
    long long ticks[2];
    for (int k = 0; k < 2; ++k) {
        const long long centre = planeTicks(plane, diameter, c, k);
        ticks[k] = absolute ? centre : centre - planeTicks(plane, diameter, from, k);
    }
    appendWordPair(out, std::string_view(&plane.centre[0], 1), ticks[0],
                   std::string_view(&plane.centre[1], 1), ticks[1]);
}

/// True when `p` and `q` are written as the same point: a block between
/// them would not move (an arc would even run as a full circle).
bool samePoint(const ScannedBlock& s, const CompilerPlane& plane, const Point2& p,
               const Point2& q) {
    for (int k = 0; k < 2; ++k)
        if (planeTicks(plane, s.diameter, p, k) != planeTicks(plane, s.diameter, q, k))
            return false;
    return true;
}

/// The words of the inserted block.
std::string insertedText(const ScannedBlock& a, const CompilerPlane& plane, CornerKind kind,
                         const CornerFit& fit) {
    std::string text;
    text.reserve(48);
    text = kind == CornerKind::Chamfer ? "G1 " : (fit.ccw ? "G3 " : "G2 ");
    appendPlaneWords(text, plane, a.diameter, a.absolute, fit.pointA, fit.pointB);
    if (kind == CornerKind::Rounding) {
        text += ' ';
        appendCentreWords(text, plane, a.diameter, a.absolute, fit.pointA, fit.center);
    }
    return text;
}

/// One blank between words, none at the start or the end; the comment keeps
/// its own spacing. Works in place.
void squeezeBlanks(std::string& text) {
    const std::size_t comment = commentOffset(text);
    char* const data = text.data();  // a plain pointer: no reload of the string per character
    const std::size_t size = text.size();
    std::size_t kept = 0;
    for (std::size_t i = 0; i < comment; ++i) {  // the words; the comment as it is
        const char c = data[i];
        if (c == ' ' && (kept == 0 || data[kept - 1] == ' ')) continue;
        data[kept++] = c;
    }
    if (kept != comment) std::memmove(data + kept, data + comment, size - comment);
    kept += size - comment;
    while (kept > 0 && data[kept - 1] == ' ')
        --kept;
    text.resize(kept);
}

/// True when squeezeBlanks leaves `text` (its comment at `comment`) as it is.
bool squeezed(std::string_view text, std::size_t comment) {
    if (text.empty()) return true;
    if (text.front() == ' ' || text.back() == ' ') return false;
    for (std::size_t i = 1; i < comment; ++i)
        if (text[i] == ' ' && text[i - 1] == ' ') return false;
    return true;
}

/// Buffers editedText reuses from block to block.
struct EditScratch {
    struct Span {
        std::size_t begin, end;
    };
    std::vector<Span> remove;
    std::string insert;
    std::string out;
};

/// Applies `edit` to the text of a motion block scanned as `s`; the result
/// is left in `scratch.out`. Returns false (nothing written) when the text
/// stays as it is.
bool editedText(const std::string& text, const ScannedBlock& s, const ScanResult& scan,
                const BlockEdit& edit, EditScratch& scratch) {
    using Span = EditScratch::Span;
    std::vector<Span>& remove = scratch.remove;
    std::string& insert = scratch.insert;
    std::string& out = scratch.out;
    remove.clear();
    insert.clear();
    out.clear();
    const CompilerPlane& plane = scan.planeOf(s);
    const bool geometry = edit.consumed || edit.newEnd || (edit.newStart && !s.absolute);
    if (geometry) {
        for (std::uint32_t a = s.axes.begin; a < s.axes.end; ++a) {
            const ScannedWord& w = scan.axisWords[a];
            if (sameAxisName(w.name, plane.axis[0]) || sameAxisName(w.name, plane.axis[1]))
                remove.push_back({w.begin, w.end});
        }
        const Point2 start = edit.newStart.value_or(s.element.start);
        const Point2 end = edit.newEnd.value_or(s.element.end);
        if (!edit.consumed) appendPlaneWords(insert, plane, s.diameter, s.absolute, start, end);
        if (s.element.arc && (edit.consumed || !s.absolute)) {
            for (std::uint32_t c = s.centres.begin; c < s.centres.end; ++c)
                remove.push_back({scan.centreWords[c].begin, scan.centreWords[c].end});
            if (!edit.consumed) {
                insert += ' ';
                appendCentreWords(insert, plane, s.diameter, false, start, s.element.center);
            }
        }
    }
    const std::size_t comment = commentOffset(text);
    // a new start of an absolute block: nothing to write but the squeeze
    if (!geometry && !edit.removeCorner && edit.prependG < 0 && squeezed(text, comment))
        return false;
    if (edit.removeCorner) remove.push_back({s.cornerBegin, s.cornerEnd});
    std::sort(remove.begin(), remove.end(), [](Span x, Span y) { return x.begin < y.begin; });
    std::size_t insertAt = remove.empty() || !geometry ? comment : remove.front().begin;
    if (edit.prependG >= 0) {
        out += 'G';
        appendTicks(out, static_cast<long long>(edit.prependG) * 10000);  // the number, no fraction
        out += ' ';
    }
    std::size_t copied = 0;
    auto putInsert = [&] {
        out += ' ';
        out += insert;
        out += ' ';
        insert.clear();
    };
    for (const Span& span : remove) {
        if (span.begin < copied || span.end > text.size()) continue;
        out.append(text, copied, span.begin - copied);
        if (span.begin == insertAt && !insert.empty()) putInsert();
        copied = span.end;
    }
    if (!insert.empty() && insertAt >= copied) {
        out.append(text, copied, insertAt - copied);
        copied = insertAt;
        putInsert();
    }
    out.append(text, copied, std::string::npos);
    squeezeBlanks(out);
    return true;
}

class CornerJob {
  public:
    CornerJob(BlockSequence& blocks, CompileContext& context, const ScanResult& scan)
        : blocks_(blocks),
          context_(context),
          scan_(scan),
          scanned_(scan.blocks),
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
    bool reportMotion(std::size_t i, std::size_t m, const char* which);

    BlockSequence& blocks_;
    CompileContext& context_;
    const ScanResult& scan_;
    const std::vector<ScannedBlock>& scanned_;
    std::vector<BlockEdit> edits_;
    std::vector<double> minimum_;  // path length of a motion block already used by a corner
    std::vector<Insertion> insertions_;
};

bool CornerJob::checkMotion(std::size_t i, std::size_t m, const char* which) {
    const ScannedBlock& s = scanned_[m];
    const bool contour = s.motionG == 1 || s.motionG == 2 || s.motionG == 3;
    if (!contour || s.outOfPlane || s.planeVariable || !s.startKnown || !s.validElement)
        return reportMotion(i, m, which);
    return true;
}

bool CornerJob::reportMotion(std::size_t i, std::size_t m, const char* which) {
    const ScannedBlock& s = scanned_[m];
    const std::string id = shortId(blocks_, m);  // only built for a message
    if (s.motionG != 1 && s.motionG != 2 && s.motionG != 3)
        return fail(i, "COMPILER_CFRD_NOT_CONTOUR", "CF/RD needs G1, G2 or G3 motion.",
                    {std::string("The ") + which + " motion block " + id +
                     " is a rapid traverse (G0)."}) &&
               false;
    if (s.outOfPlane)
        return fail(i, "COMPILER_CFRD_OUT_OF_PLANE", "CF/RD: motion outside the plane.",
                    {std::string("The ") + which + " motion block " + id +
                     " moves an axis outside the active plane G" +
                     std::to_string(scan_.planeOf(s).code) + "."}) &&
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
                    {std::string("The ") + which + " motion block " + id + ": " +
                     (s.elementProblem ? s.elementProblem : "") + "."}) &&
               false;
    return true;
}

bool CornerJob::corner(std::size_t i) {
    const ScannedBlock& c = scanned_[i];
    if (c.cornerCount > 1)
        return fail(i, "COMPILER_CFRD_TWICE", "Only one CF or RD per block.",
                    {"The block holds more than one chamfer/rounding instruction."});
    if (c.sizeProblem)
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
    int between = c.motion ? 0 : 1;  // an own CF/RD block lies between the motion blocks too
    std::size_t illegalAt = 0;       // 0: none (block 0 never lies between)
    for (; b < blocks_.size() && !blocks_[b].programEnd; ++b) {
        if (illegalAt == 0 && scanned_[b].illegal) illegalAt = b;
        if (scanned_[b].motion) break;
        if (++between > kMaxBlocksBetween) break;
    }
    if (b >= blocks_.size() || blocks_[b].programEnd || between > kMaxBlocksBetween)
        return fail(i, "COMPILER_CFRD_NO_TARGET", "No motion block found for CF/RD.",
                    {"The next motion block is missing, or more than 20 blocks without motion "
                     "follow the first motion block."});
    if (illegalAt > 0)
        return fail(i, "COMPILER_CFRD_ILLEGAL", "CF/RD across an illegal function.",
                    {"Between the two motion blocks (up to " + shortId(blocks_, b) + ") " +
                     describeIllegal(scanned_[illegalAt]) +
                     " is programmed; no chamfer or rounding is possible there."});
    if (!checkMotion(i, a, "first") || !checkMotion(i, b, "second")) return !context_.stopped();
    const ScannedBlock& sa = scanned_[a];
    const ScannedBlock& sb = scanned_[b];
    CornerFit fit = fitCorner(c.kind, sa.element, minimum_[a], sb.element, c.size);
    const CompilerPlane& planeA = scan_.planeOf(sa);
    if (fit.applied > 0.0 && samePoint(sa, planeA, fit.pointA, fit.pointB)) {
        // smaller than what is written (0.0001): the inserted block would not
        // move, an inserted arc would run as a full circle
        fit = CornerFit{};
        fit.reduced = true;
    }
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
    // An element used up by its corners disappears: a block from a point to
    // itself would not move, and an arc would run as a full circle.
    if (samePoint(sa, planeA, edits_[a].newStart.value_or(sa.element.start), fit.pointA))
        edits_[a].consumed = true;
    if (samePoint(sb, scan_.planeOf(sb), fit.pointB, sb.element.end)) edits_[b].consumed = true;
    minimum_[b] = sb.element.parameterOf(fit.pointB);
    const int insertedG = c.kind == CornerKind::Chamfer ? 1 : (fit.ccw ? 3 : 2);
    if (!sb.explicitMotionG && sb.motionG != insertedG) edits_[b].prependG = sb.motionG;
    insertions_.push_back({i, insertedText(sa, planeA, c.kind, fit)});
    return true;
}

void CornerJob::apply() {
    EditScratch scratch;
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
        const BlockEdit& e = edits_[i];
        if (!e.newStart && !e.newEnd && !e.consumed && !e.removeCorner && e.prependG < 0) continue;
        if (editedText(blocks_[i].text, scanned_[i], scan_, e, scratch))
            blocks_[i].text.swap(scratch.out);  // the old text's buffer is the next scratch
        blocks_[i].changed = true;
    }
    if (insertions_.empty()) return;
    // one new sequence: every block moved once, each insertion right after
    // the block it belongs to (insertions_ are in block order)
    BlockSequence merged;
    merged.reserve(blocks_.size() + insertions_.size());
    std::size_t next = 0;
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
        merged.push_back(std::move(blocks_[i]));
        for (; next < insertions_.size() && insertions_[next].at == i; ++next) {
            const CompileBlock& owner = merged.back();
            CompileBlock& block = merged.emplace_back();
            block.number = owner.number;
            block.sourceIndex = owner.sourceIndex;
            block.sourceLine = owner.sourceLine;
            block.intermediate = true;
            block.changed = true;
            block.text = std::move(insertions_[next].text);
        }
    }
    blocks_.swap(merged);
}

}  // namespace

void ChamferRoundPass::run(BlockSequence& blocks, CompileContext& context) const {
    bool any = false;
    for (const CompileBlock& block : blocks)
        if (block.text.find("CF") != std::string::npos ||
            block.text.find("RD") != std::string::npos) {
            any = true;
            break;
        }
    if (!any) return;
    const ScanResult scan = scanBlocks(blocks, context.parsed(blocks), context.options());
    CornerJob job(blocks, context, scan);
    for (std::size_t i = 0; i < blocks.size(); ++i)
        if (scan.blocks[i].cornerCount > 0 && !context.hasError(blocks[i]) && !job.corner(i))
            return;
    if (context.stopped()) return;
    job.apply();
}

}  // namespace mtc::core
