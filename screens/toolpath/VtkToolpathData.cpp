#include "screens/toolpath/VtkToolpathData.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>

#include "screens/toolpath/ToolpathPalette.h"

namespace mtc::screens {

namespace {
using mtc::core::ToolpathGeometry;
using mtc::core::ToolpathLayer;

const ToolpathLayer& layerOf(const ToolpathGeometry& g, bool developed) {
    return developed ? g.developed : g.scene;
}

std::pair<std::uint32_t, std::uint32_t> rangeOf(const ToolpathGeometry& g, bool developed,
                                                std::size_t move) {
    return developed ? g.developedRange(move) : g.sceneRange(move);
}

vtkSmartPointer<vtkPoints> pointsOf(const ToolpathLayer& layer) {
    auto data = vtkSmartPointer<vtkFloatArray>::New();
    data->SetNumberOfComponents(3);
    data->SetNumberOfTuples(static_cast<vtkIdType>(layer.vertexCount()));
    std::copy(layer.xyz.begin(), layer.xyz.end(), data->GetPointer(0));
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(data);
    return points;
}

/// Line cells from pairs of vertex indices (a, b) in `ends`.
vtkSmartPointer<vtkCellArray> linesOf(const std::vector<std::int32_t>& ends) {
    const auto count = static_cast<vtkIdType>(ends.size() / 2);
    auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
    offsets->SetNumberOfValues(count + 1);
    std::int32_t* o = offsets->GetPointer(0);
    for (vtkIdType i = 0; i <= count; ++i)
        o[i] = static_cast<std::int32_t>(2 * i);
    auto connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(ends.size()));
    std::copy(ends.begin(), ends.end(), connectivity->GetPointer(0));
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->SetData(offsets, connectivity);
    return cells;
}

vtkSmartPointer<vtkUnsignedCharArray> newColours(std::size_t cells) {
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetName("colours");
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(static_cast<vtkIdType>(cells));
    return colours;
}

void setColour(unsigned char* rgb, const QColor& colour) {
    rgb[0] = static_cast<unsigned char>(colour.red());
    rgb[1] = static_cast<unsigned char>(colour.green());
    rgb[2] = static_cast<unsigned char>(colour.blue());
}

vtkSmartPointer<vtkPolyData> assemble(const ToolpathLayer& layer,
                                      const std::vector<std::int32_t>& ends,
                                      vtkSmartPointer<vtkUnsignedCharArray> colours,
                                      vtkPoints* points) {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    if (points)
        poly->SetPoints(points);
    else
        poly->SetPoints(pointsOf(layer));
    poly->SetLines(linesOf(ends));
    if (colours) poly->GetCellData()->SetScalars(colours);
    return poly;
}
}  // namespace

vtkSmartPointer<vtkPolyData> toolpathPolyData(const ToolpathGeometry& geometry, bool developed,
                                              const ToolpathPalette& palette) {
    const ToolpathLayer& layer = layerOf(geometry, developed);
    const std::size_t count = layer.segmentCount();
    auto colours = newColours(count);
    unsigned char* rgb = colours->GetPointer(0);
    for (std::size_t m = 0; m < geometry.moves.size(); ++m) {
        const auto [first, last] = rangeOf(geometry, developed, m);
        unsigned char c[3];
        setColour(c, palette.colour(geometry.moves[m].kind));
        for (std::uint32_t s = first; s < last; ++s)
            std::copy(c, c + 3, rgb + 3 * static_cast<std::size_t>(s));
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(pointsOf(layer));
    auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
    offsets->SetNumberOfValues(static_cast<vtkIdType>(count + 1));
    auto connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(2 * count));
    std::int32_t* o = offsets->GetPointer(0);
    std::int32_t* c = connectivity->GetPointer(0);
    for (std::size_t i = 0; i < count; ++i) {
        o[i] = static_cast<std::int32_t>(2 * i);
        c[2 * i] = static_cast<std::int32_t>(layer.segmentStart[i]);
        c[2 * i + 1] = static_cast<std::int32_t>(layer.segmentStart[i] + 1);
    }
    o[count] = static_cast<std::int32_t>(2 * count);
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->SetData(offsets, connectivity);
    poly->SetLines(cells);
    poly->GetCellData()->SetScalars(colours);
    return poly;
}

vtkSmartPointer<vtkPolyData> toolpathLevelOfDetail(const ToolpathGeometry& geometry, bool developed,
                                                   const ToolpathPalette& palette,
                                                   std::size_t maxSegments, vtkPoints* points) {
    const ToolpathLayer& layer = layerOf(geometry, developed);
    const std::size_t count = layer.segmentCount();
    if (count <= maxSegments || maxSegments == 0)
        return toolpathPolyData(geometry, developed, palette);
    const std::size_t stride = (count + maxSegments - 1) / maxSegments;
    std::vector<std::int32_t> ends;
    std::vector<QColor> colours;
    ends.reserve(2 * (maxSegments + maxSegments / 4));
    std::size_t move = 0;
    std::size_t s = 0;
    while (s < count) {
        // A run: up to `stride` segments that follow each other on one chain.
        std::size_t e = s + 1;
        while (e < count && e - s < stride &&
               layer.segmentStart[e] == layer.segmentStart[e - 1] + 1)
            ++e;
        while (move + 1 < geometry.moves.size() &&
               rangeOf(geometry, developed, move + 1).first <= s)
            ++move;
        ends.push_back(static_cast<std::int32_t>(layer.segmentStart[s]));
        ends.push_back(static_cast<std::int32_t>(layer.segmentStart[e - 1] + 1));
        colours.push_back(palette.colour(geometry.moves.empty() ? mtc::core::ToolpathKind::Feed
                                                                : geometry.moves[move].kind));
        s = e;
    }
    auto rgb = newColours(colours.size());
    for (std::size_t i = 0; i < colours.size(); ++i)
        setColour(rgb->GetPointer(static_cast<vtkIdType>(3 * i)), colours[i]);
    return assemble(layer, ends, rgb, points);
}

vtkSmartPointer<vtkPolyData> toolpathMoves(const ToolpathGeometry& geometry, bool developed,
                                           const std::vector<std::uint32_t>& moves,
                                           vtkPoints* points) {
    const ToolpathLayer& layer = layerOf(geometry, developed);
    std::vector<std::int32_t> ends;
    for (std::uint32_t m : moves) {
        if (m >= geometry.moves.size()) continue;
        const auto [first, last] = rangeOf(geometry, developed, m);
        for (std::uint32_t s = first; s < last; ++s) {
            ends.push_back(static_cast<std::int32_t>(layer.segmentStart[s]));
            ends.push_back(static_cast<std::int32_t>(layer.segmentStart[s] + 1));
        }
    }
    return assemble(layer, ends, nullptr, points);
}

}  // namespace mtc::screens
