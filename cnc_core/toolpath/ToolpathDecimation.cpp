#include "cnc_core/toolpath/ToolpathDecimation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mtc::core {

namespace {

/// Consecutive segments [first, first + count) on one chain (and one kind
/// unless kinds are joined); its vertices follow each other in the layer.
struct Run {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    ToolpathKind kind = ToolpathKind::Feed;
};

std::uint32_t firstOf(const ToolpathMove& m, bool developed) {
    return developed ? m.firstDeveloped : m.firstScene;
}

/// Segments of one run at most (unless the budget needs longer ones):
/// bounds the work of one Douglas-Peucker pass (its depth) and lets a try
/// stop early once over the budget.
constexpr std::size_t kLongestRun = 4096;

/// Largest tolerance of the coarse copy as a share of the layer's extent.
constexpr double kLargestToleranceShare = 1.0 / 20.0;

/// Runs in the sample of a large path's first guess (sampledGuess).
constexpr std::size_t kSampleRuns = 64;

/// Runs of the layer in segment order; a new run starts where a chain
/// breaks, (unless `joinKinds`) where the move kind changes, and after
/// `longest` segments.
std::vector<Run> runsOf(const ToolpathGeometry& g, bool developed, bool joinKinds,
                        std::size_t longest) {
    const ToolpathLayer& layer = developed ? g.developed : g.scene;
    const std::size_t count = layer.segmentCount();
    std::vector<Run> runs;
    std::size_t move = 0;
    for (std::size_t s = 0; s < count; ++s) {
        while (move + 1 < g.moves.size() && firstOf(g.moves[move + 1], developed) <= s)
            ++move;
        const ToolpathKind kind = g.moves.empty() ? ToolpathKind::Feed : g.moves[move].kind;
        const bool continues = !runs.empty() && runs.back().count < longest &&
                               layer.segmentStart[s] == layer.segmentStart[s - 1] + 1 &&
                               (joinKinds || runs.back().kind == kind);
        if (continues)
            ++runs.back().count;
        else
            runs.push_back({static_cast<std::uint32_t>(s), 1, kind});
    }
    return runs;
}

/// Douglas-Peucker over the vertices of `run`: marks in `keep` (one flag
/// per vertex of the run) the vertices that must stay for `tolerance`.
void simplify(const ToolpathLayer& layer, const Run& run, double tolerance,
              std::vector<std::uint8_t>& keep,
              std::vector<std::pair<std::uint32_t, std::uint32_t>>& stack) {
    const std::uint32_t base = layer.segmentStart[run.first];
    keep.assign(run.count + 1, 0);
    keep.front() = keep.back() = 1;
    stack.clear();
    if (run.count > 1) stack.emplace_back(0, run.count);
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        const auto a = layer.vertex(base + i);
        const auto b = layer.vertex(base + j);
        double worst = -1.0;
        std::uint32_t at = i;
        for (std::uint32_t k = i + 1; k < j; ++k) {
            const double d = distanceToSegment(layer.vertex(base + k), a, b);
            if (d > worst) {
                worst = d;
                at = k;
            }
        }
        if (worst <= tolerance) continue;
        keep[at] = 1;
        if (at - i > 1) stack.emplace_back(i, at);
        if (j - at > 1) stack.emplace_back(at, j);
    }
}

/// Appends the cells of `run` kept by `keep` to `out`.
void emit(const ToolpathLayer& layer, const Run& run, const std::vector<std::uint8_t>& keep,
          DecimatedLayer& out) {
    const std::uint32_t base = layer.segmentStart[run.first];
    std::uint32_t from = 0;
    for (std::uint32_t k = 1; k <= run.count; ++k) {
        if (!keep[k]) continue;
        out.ends.push_back(base + from);
        out.ends.push_back(base + k);
        out.firstSegment.push_back(run.first + from);
        out.kinds.push_back(run.kind);
        from = k;
    }
}

/// One try with `tolerance`; false (and `out` incomplete) when the cells
/// would be more than `budget`.
bool tryDecimate(const ToolpathLayer& layer, const std::vector<Run>& runs, double tolerance,
                 std::size_t budget, DecimatedLayer& out) {
    out = {};
    out.tolerance = tolerance;
    std::vector<std::uint8_t> keep;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack;
    for (const Run& run : runs) {
        simplify(layer, run, tolerance, keep, stack);
        emit(layer, run, keep, out);
        if (out.cellCount() > budget) return false;
    }
    return true;
}

/// Last resort: one cell per run for every n-th run, at most `budget`.
DecimatedLayer everyNthRun(const ToolpathLayer& layer, const std::vector<Run>& runs,
                           std::size_t budget) {
    DecimatedLayer out;
    out.tolerance = std::numeric_limits<double>::infinity();
    out.dropped = runs.size() > budget;
    const std::size_t step = budget == 0 ? runs.size() + 1 : (runs.size() + budget - 1) / budget;
    for (std::size_t r = 0; r < runs.size(); r += std::max<std::size_t>(step, 1)) {
        const Run& run = runs[r];
        const std::uint32_t base = layer.segmentStart[run.first];
        out.ends.push_back(base);
        out.ends.push_back(base + run.count);
        out.firstSegment.push_back(run.first);
        out.kinds.push_back(run.kind);
    }
    return out;
}

/// Where the search of a large path starts (sampledGuess).
struct SearchStart {
    double tolerance = 0.0;
    std::size_t thinning = 1;  ///< > 1: keep every n-th run at the largest tolerance
};

/// Where the search for the tolerance of a large path starts: the
/// tolerance, doubling from `tolerance` up to `largest`, at which every
/// k-th run (about kSampleRuns of them) keeps its share of the budget, one
/// doubling back for the sample's error; when even `largest` does not keep
/// it, the share of the runs the budget holds at `largest`. A try over
/// every run of a million-move path costs 0.1-0.5 s, and most tries fail.
SearchStart sampledGuess(const ToolpathLayer& layer, const std::vector<Run>& runs, double tolerance,
                         double largest, std::size_t budget) {
    const std::size_t every = runs.size() / kSampleRuns;
    if (every < 2) return {tolerance, 1};
    std::vector<Run> sample;
    for (std::size_t r = 0; r < runs.size(); r += every)
        sample.push_back(runs[r]);
    const std::size_t share = std::max<std::size_t>(budget * sample.size() / runs.size(), 1);
    DecimatedLayer scratch;
    double tol = tolerance;
    while (tol < largest) {
        if (tryDecimate(layer, sample, tol, share, scratch))
            return {std::max(tolerance, tol / 2.0), 1};
        tol *= 2.0;
    }
    tryDecimate(layer, sample, largest, std::numeric_limits<std::size_t>::max(), scratch);
    const double needed = static_cast<double>(scratch.cellCount()) / static_cast<double>(share);
    std::size_t thinning = 1;
    while (thinning < needed / 2.0 && thinning < runs.size())  // one step back, as above
        thinning *= 2;
    return {largest, thinning};
}

/// The runs r = 0, n, 2n, ... simplified with `tolerance`, for the smallest
/// n = 2^k that keeps the budget: a path that retraces itself many times
/// (a contour repeated over and over) shows a share of its passes, each
/// still drawn within the tolerance.
DecimatedLayer everyNthRunAt(const ToolpathLayer& layer, const std::vector<Run>& runs,
                             double tolerance, std::size_t budget, std::size_t firstStep) {
    std::vector<Run> kept;
    DecimatedLayer out;
    for (std::size_t step = std::max<std::size_t>(firstStep, 2); step < runs.size(); step *= 2) {
        kept.clear();
        for (std::size_t r = 0; r < runs.size(); r += step)
            kept.push_back(runs[r]);
        if (tryDecimate(layer, kept, tolerance, budget, out)) {
            out.dropped = true;
            return out;
        }
    }
    return everyNthRun(layer, runs, budget);
}

}  // namespace

std::pair<std::uint32_t, std::uint32_t> DecimatedLayer::segmentsOf(std::size_t cell) const {
    const std::uint32_t first = firstSegment[cell];
    return {first, first + (ends[2 * cell + 1] - ends[2 * cell])};
}

double distanceToSegment(const std::array<double, 3>& point, const std::array<double, 3>& a,
                         const std::array<double, 3>& b) {
    double ab[3], ap[3];
    double lengthSquared = 0.0, along = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
        ab[i] = b[i] - a[i];
        ap[i] = point[i] - a[i];
        lengthSquared += ab[i] * ab[i];
        along += ab[i] * ap[i];
    }
    const double t = lengthSquared > 0.0 ? std::clamp(along / lengthSquared, 0.0, 1.0) : 0.0;
    double squared = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
        const double d = ap[i] - t * ab[i];
        squared += d * d;
    }
    return std::sqrt(squared);
}

DecimatedLayer decimateLayer(const ToolpathGeometry& g, bool developed, double tolerance,
                             std::size_t budget) {
    const ToolpathLayer& layer = developed ? g.developed : g.scene;
    // Long runs are cut into pieces, never into more than half the budget.
    const std::size_t longest =
        std::max(kLongestRun, layer.segmentCount() / std::max<std::size_t>(budget / 2, 1) + 1);
    std::vector<Run> runs = runsOf(g, developed, false, longest);
    if (runs.size() > budget) runs = runsOf(g, developed, true, longest);
    if (runs.size() > budget) return everyNthRun(layer, runs, budget);
    const double size = std::max(layer.bounds.size(), 1e-3);
    double tol = std::max(tolerance, size * 1e-9);
    // Beyond this share of the picture a cell no longer follows the path
    // (TP-010): a path that retraces itself is thinned out instead.
    const double largest = std::max(tol, size * kLargestToleranceShare);
    const SearchStart start = sampledGuess(layer, runs, tol, largest, budget);
    if (start.thinning > 1) return everyNthRunAt(layer, runs, largest, budget, start.thinning);
    DecimatedLayer out;
    tol = start.tolerance;
    while (tol < largest) {  // doubling: ends within log2(largest / tol) tries
        if (tryDecimate(layer, runs, tol, budget, out)) return out;
        tol *= 2.0;
    }
    if (tryDecimate(layer, runs, largest, budget, out)) return out;
    return everyNthRunAt(layer, runs, largest, budget, 2);
}

}  // namespace mtc::core
