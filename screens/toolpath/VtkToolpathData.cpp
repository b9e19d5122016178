#include "screens/toolpath/VtkToolpathData.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <vector>

#include "screens/toolpath/ToolpathPalette.h"

namespace mtc::screens {

namespace {
using mtc::core::DecimatedLayer;
using mtc::core::ToolpathGeometry;
using mtc::core::ToolpathKind;
using mtc::core::ToolpathLayer;
using Rgb = std::array<unsigned char, 3>;

const ToolpathLayer& layerOf(const ToolpathGeometry& g, bool developed) {
    return developed ? g.developed : g.scene;
}

std::uint32_t firstOf(const mtc::core::ToolpathMove& m, bool developed) {
    return developed ? m.firstDeveloped : m.firstScene;
}

Rgb rgbOf(const QColor& colour) {
    return {static_cast<unsigned char>(colour.red()), static_cast<unsigned char>(colour.green()),
            static_cast<unsigned char>(colour.blue())};
}

/// Points, point colours and line cells filled in place (sizes known up front).
struct Builder {
    vtkSmartPointer<vtkFloatArray> xyz = vtkSmartPointer<vtkFloatArray>::New();
    vtkSmartPointer<vtkUnsignedCharArray> colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    vtkSmartPointer<vtkTypeInt32Array> offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
    vtkSmartPointer<vtkTypeInt32Array> connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
    std::int32_t points = 0, cells = 0;

    Builder(std::size_t maxPoints, std::size_t cellCount) {
        xyz->SetNumberOfComponents(3);
        xyz->SetNumberOfTuples(static_cast<vtkIdType>(maxPoints));
        colours->SetName("colours");
        colours->SetNumberOfComponents(3);
        colours->SetNumberOfTuples(static_cast<vtkIdType>(maxPoints));
        offsets->SetNumberOfValues(static_cast<vtkIdType>(cellCount) + 1);
        connectivity->SetNumberOfValues(2 * static_cast<vtkIdType>(cellCount));
    }
    /// Appends vertex `index` of `layer` with colour `rgb`; returns its point id.
    std::int32_t point(const ToolpathLayer& layer, std::size_t index, const Rgb& rgb) {
        const float* from = layer.xyz.data() + 3 * index;
        float* to = xyz->GetPointer(3 * static_cast<vtkIdType>(points));
        to[0] = from[0];
        to[1] = from[1];
        to[2] = from[2];
        unsigned char* c = colours->GetPointer(3 * static_cast<vtkIdType>(points));
        c[0] = rgb[0];
        c[1] = rgb[1];
        c[2] = rgb[2];
        return points++;
    }
    void line(std::int32_t a, std::int32_t b) {
        offsets->SetValue(cells, 2 * cells);
        connectivity->SetValue(2 * cells, a);
        connectivity->SetValue(2 * cells + 1, b);
        ++cells;
    }
    vtkSmartPointer<vtkPolyData> finish(bool withColours) {
        offsets->SetValue(cells, 2 * cells);
        offsets->SetNumberOfValues(cells + 1);  // fewer cells when repeats were dropped
        connectivity->SetNumberOfValues(2 * static_cast<vtkIdType>(cells));
        xyz->SetNumberOfTuples(points);  // keeps the memory; shrinks the count
        colours->SetNumberOfTuples(points);
        auto pts = vtkSmartPointer<vtkPoints>::New();
        pts->SetData(xyz);
        auto lines = vtkSmartPointer<vtkCellArray>::New();
        lines->SetData(offsets, connectivity);
        auto poly = vtkSmartPointer<vtkPolyData>::New();
        poly->SetPoints(pts);
        poly->SetLines(lines);
        if (withColours) poly->GetPointData()->SetScalars(colours);
        return poly;
    }
};

/// Remembers the segments drawn so far to drop exact repeats (TP-022): a
/// contour programmed over and over draws the same few hundred lines a
/// million times, and llvmpipe rasterises every one of them (seconds per
/// frame) for no pixel of difference. A two-way set-associative table of
/// recent segments: fixed memory (about 460 KB), two probes per segment; a
/// repeat whose set two other segments took meanwhile is drawn again.
class RepeatFilter {
  public:
    /// True when the segment a-b (either direction) of `kind` was seen before.
    bool repeated(const float* a, const float* b, ToolpathKind kind) {
        Key key{};
        std::memcpy(key.bits.data(), a, 3 * sizeof(float));
        std::memcpy(key.bits.data() + 3, b, 3 * sizeof(float));
        // The same line travelled back draws the same pixels.
        if (std::lexicographical_compare(key.bits.begin() + 3, key.bits.begin() + 6,
                                         key.bits.begin(), key.bits.begin() + 3))
            std::swap_ranges(key.bits.begin(), key.bits.begin() + 3, key.bits.begin() + 3);
        key.bits[6] = static_cast<std::uint32_t>(kind) + 1;  // 0 = empty entry
        Set& set = sets_[hash(key) & (kSets - 1)];
        if (set.ways[0].bits == key.bits || set.ways[1].bits == key.bits) return true;
        set.ways[set.older] = key;
        set.older ^= 1;
        return false;
    }

  private:
    static constexpr std::size_t kSets = std::size_t{1} << 13;
    struct Key {
        std::array<std::uint32_t, 7> bits;  ///< two points' float bits, kind + 1
    };
    struct Set {
        std::array<Key, 2> ways;
        std::uint32_t older = 0;  ///< the way replaced next
    };
    static std::uint64_t hash(const Key& key) {
        std::uint64_t h = 0x9E3779B97F4A7C15ull;
        for (std::uint32_t word : key.bits)
            h = (h ^ word) * 0xFF51AFD7ED558CCDull;
        h ^= h >> 33;  // the final mix of MurmurHash3: every bit reaches the low ones
        h *= 0xC4CEB9FE1A85EC53ull;
        return h ^ (h >> 33);
    }
    std::vector<Set> sets_ = std::vector<Set>(kSets, Set{});
};

/// Number of places where a chain goes on with another kind (extra points).
std::size_t colourBreaks(const ToolpathGeometry& g, bool developed) {
    const ToolpathLayer& layer = layerOf(g, developed);
    std::size_t breaks = 0;
    for (std::size_t m = 1; m < g.moves.size(); ++m) {
        const std::uint32_t s = firstOf(g.moves[m], developed);
        if (s == 0 || s >= layer.segmentCount()) continue;
        if (g.moves[m].kind != g.moves[m - 1].kind) ++breaks;
    }
    return breaks;
}
}  // namespace

vtkSmartPointer<vtkPolyData> toolpathPolyData(const ToolpathGeometry& geometry, bool developed,
                                              const ToolpathPalette& palette, bool dropRepeats) {
    const ToolpathLayer& layer = layerOf(geometry, developed);
    const std::size_t count = layer.segmentCount();
    Builder b(layer.vertexCount() + colourBreaks(geometry, developed), count);
    std::array<Rgb, mtc::core::kToolpathKinds> rgb{};
    for (int k = 0; k < mtc::core::kToolpathKinds; ++k)
        rgb[static_cast<std::size_t>(k)] = rgbOf(palette.colour(static_cast<ToolpathKind>(k)));
    std::optional<RepeatFilter> repeats;
    if (dropRepeats) repeats.emplace();
    std::size_t move = 0;
    std::int32_t last = -1;  // point id of the previous segment's end
    bool lastDrawn = false;  // the previous segment has a cell (its end point is `last`)
    ToolpathKind previous = ToolpathKind::Feed;
    for (std::size_t s = 0; s < count; ++s) {
        while (move + 1 < geometry.moves.size() &&
               firstOf(geometry.moves[move + 1], developed) <= s)
            ++move;
        const auto kind = geometry.moves.empty() ? ToolpathKind::Feed : geometry.moves[move].kind;
        const std::uint32_t v = layer.segmentStart[s];
        const float* ends = layer.xyz.data() + 3 * static_cast<std::size_t>(v);
        if (repeats && repeats->repeated(ends, ends + 3, kind)) {
            lastDrawn = false;
            continue;
        }
        const Rgb& c = rgb[static_cast<std::size_t>(kind)];
        const bool chained =
            lastDrawn && s > 0 && v == layer.segmentStart[s - 1] + 1 && kind == previous;
        const std::int32_t from = chained ? last : b.point(layer, v, c);
        last = b.point(layer, v + 1, c);
        b.line(from, last);
        lastDrawn = true;
        previous = kind;
    }
    return b.finish(true);
}

vtkSmartPointer<vtkPolyData> toolpathLevelOfDetail(const ToolpathGeometry& geometry, bool developed,
                                                   const ToolpathPalette& palette,
                                                   const DecimatedLayer& coarse) {
    const ToolpathLayer& layer = layerOf(geometry, developed);
    Builder b(2 * coarse.cellCount(), coarse.cellCount());
    for (std::size_t i = 0; i < coarse.cellCount(); ++i) {
        const Rgb c = rgbOf(palette.colour(coarse.kinds[i]));
        const std::int32_t from = b.point(layer, coarse.ends[2 * i], c);
        b.line(from, b.point(layer, coarse.ends[2 * i + 1], c));
    }
    return b.finish(true);
}

vtkSmartPointer<vtkPolyData> toolpathMoves(const ToolpathGeometry& geometry, bool developed,
                                           const std::vector<std::uint32_t>& moves) {
    const ToolpathLayer& layer = layerOf(geometry, developed);
    std::size_t count = 0;
    for (std::uint32_t m : moves) {
        if (m >= geometry.moves.size()) continue;
        const auto [first, last] = developed ? geometry.developedRange(m) : geometry.sceneRange(m);
        count += last - first;
    }
    Builder b(2 * count, count);
    for (std::uint32_t m : moves) {
        if (m >= geometry.moves.size()) continue;
        const auto [first, last] = developed ? geometry.developedRange(m) : geometry.sceneRange(m);
        for (std::uint32_t s = first; s < last; ++s) {
            const std::int32_t from = b.point(layer, layer.segmentStart[s], Rgb{});
            b.line(from, b.point(layer, layer.segmentStart[s] + 1, Rgb{}));
        }
    }
    return b.finish(false);
}

vtkSmartPointer<vtkPolyData> toolpathStretch(const ToolpathLayer& layer, std::uint32_t from,
                                             std::uint32_t to,
                                             const std::array<std::array<double, 3>, 2>* partial) {
    const std::size_t count = to > from ? to - from : 0;
    const std::size_t cells = count + (partial ? 1 : 0);  // the cell array's size is exact
    Builder b(2 * cells, cells);
    std::int32_t last = -1;
    for (std::uint32_t s = from; s < to; ++s) {
        const std::uint32_t v = layer.segmentStart[s];
        const bool chained = s > from && v == layer.segmentStart[s - 1] + 1;
        const std::int32_t start = chained ? last : b.point(layer, v, Rgb{});
        last = b.point(layer, v + 1, Rgb{});
        b.line(start, last);
    }
    if (partial) {
        ToolpathLayer ends;  // the two points of the piece
        for (const auto& p : *partial)
            for (double c : p)
                ends.xyz.push_back(static_cast<float>(c));
        const std::int32_t start = b.point(ends, 0, Rgb{});
        b.line(start, b.point(ends, 1, Rgb{}));
    }
    return b.finish(false);
}

vtkSmartPointer<vtkPolyData> toolpathContour(const ToolpathGeometry& geometry, bool developed) {
    const ToolpathLayer& layer = developed ? geometry.developedContour : geometry.contour;
    const std::size_t count = layer.segmentCount();
    Builder b(2 * count, count);
    std::int32_t last = -1;
    for (std::size_t s = 0; s < count; ++s) {
        const std::uint32_t v = layer.segmentStart[s];
        const bool chained = s > 0 && v == layer.segmentStart[s - 1] + 1;
        const std::int32_t from = chained ? last : b.point(layer, v, Rgb{});
        last = b.point(layer, v + 1, Rgb{});
        b.line(from, last);
    }
    return b.finish(false);
}

}  // namespace mtc::screens
