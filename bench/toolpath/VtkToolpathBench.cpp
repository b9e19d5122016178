// VTK part of the toolpath view (issue 8), outside ctest:
//   mtc_toolpath_bench [--arcs] [count]   geometry, poly-data and coarse copy
//                                 for `count` (1,000,000) straight moves
//                                 (--arcs: a contour with quarter arcs of
//                                 radius 10 mm): times, peak RSS
//   xvfb-run -a -s "-screen 0 1280x800x24" mtc_toolpath_bench --frames [count]
//       [--canvas] [--samples N (-1: VTK's default)] [--size W H]
//                                 frame times of an X window (Mesa llvmpipe
//                                 under Xvfb) for each way of drawing the
//                                 path: cell or point colours, line width,
//                                 the coarse copy, the grid actor
//                                 (--canvas: only what the view draws).
// Output: one line per measurement (ms, MB of the process's peak RSS).
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkCubeAxesActor.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/ProcessMeters.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/toolpath/ToolpathBuilder.h"
#include "cnc_core/toolpath/ToolpathDecimation.h"
#include "resources/EmbeddedResources.h"
#include "screens/toolpath/ToolpathPalette.h"
#include "screens/toolpath/VtkToolpathData.h"

namespace {

using mtc::bench::Clock;
using mtc::bench::msSince;
using mtc::bench::peakRssMb;

using namespace mtc::core;
/// `count` straight moves on process 0 of the demo cell: 0.1 mm segments in
/// 100 mm passes, 60 mm wide layers (what a finishing path of that size draws).
ToolpathGeometry million(int count) {
    const MachineConfig cell =
        readMachineConfig(mtc::resources::find(mtc::resources::kDemoCellName)).config;
    DiagnosticList ignored;
    ToolpathBuilder builder(ProcessAxes::build(*cell.process(0), ignored));
    Motion m;
    m.axisCount = 3;
    for (int i = 0; i < count; ++i) {
        m.start = m.end;
        // Passes of 1000 segments of 0.1 mm (a finishing path), every 100th a rapid.
        const int pass = i / 1000, step = i % 1000 + 1;
        m.type = i % 100 == 0 ? MotionType::Rapid : MotionType::Linear;
        m.end[0] = pass % 2 ? 100.0 - step * 0.1 : step * 0.1;
        m.end[1] = pass * 0.06;
        m.end[2] = -(pass / 100) * 0.5;
        m.blockIndex = static_cast<std::uint32_t>(i);
        builder.motion(m);
    }
    return builder.take();
}

/// `count` moves of a contour repeated over and over, a third of them
/// quarter arcs of radius 10 mm (the shape of the 1,000,000-block run
/// benchmark, scripts/gen-bench-program.sh): what an arc-heavy program draws.
ToolpathGeometry arcHeavy(int count) {
    const MachineConfig cell =
        readMachineConfig(mtc::resources::find(mtc::resources::kDemoCellName)).config;
    DiagnosticList ignored;
    ToolpathBuilder builder(ProcessAxes::build(*cell.process(0), ignored));
    struct Step {
        MotionType type;
        double x, y, cx, cy;
    };
    static constexpr Step kContour[] = {
        {MotionType::Linear, 10, 0, 0, 0},  {MotionType::ArcCCW, 20, 10, 10, 10},
        {MotionType::Linear, 20, 20, 0, 0}, {MotionType::ArcCW, 10, 30, 20, 30},
        {MotionType::Linear, 0, 30, 0, 0},  {MotionType::Linear, 0, 0, 0, 0}};
    Motion m;
    m.axisCount = 3;
    for (int i = 0; i < count; ++i) {
        const Step& step = kContour[i % 6];
        m.start = m.end;
        m.type = step.type;
        m.end[0] = step.x;
        m.end[1] = step.y;
        const bool arc = step.type != MotionType::Linear;
        m.planeAxis1 = arc ? 0 : -1;
        m.planeAxis2 = arc ? 1 : -1;
        m.center1 = step.cx;
        m.center2 = step.cy;
        m.blockIndex = static_cast<std::uint32_t>(i);
        builder.motion(m);
    }
    return builder.take();
}

/// The same cells with cell colours instead of point colours (the drawing
/// before TP-010's change: VTK 9.1 looks them up by gl_PrimitiveID).
vtkSmartPointer<vtkPolyData> withCellColours(vtkPolyData* full, const ToolpathGeometry& g,
                                             const mtc::screens::ToolpathPalette& palette) {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->ShallowCopy(full);
    poly->GetPointData()->SetScalars(nullptr);
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(full->GetNumberOfCells());
    for (std::size_t m = 0; m < g.moves.size(); ++m) {
        const QColor c = palette.colour(g.moves[m].kind);
        const auto [first, last] = g.sceneRange(m);
        for (std::uint32_t s = first; s < last; ++s)
            colours->SetTypedTuple(
                s, std::array<unsigned char, 3>{static_cast<unsigned char>(c.red()),
                                                static_cast<unsigned char>(c.green()),
                                                static_cast<unsigned char>(c.blue())}
                       .data());
    }
    poly->GetCellData()->SetScalars(colours);
    return poly;
}

struct Variant {
    std::string name;
    vtkPolyData* data;
    bool cellColours;
    float lineWidth;
    bool grid;
};

/// First frame after the input was set (upload) and median/max of 10
/// frames, each after turning the camera by 5 degrees.
void measure(vtkRenderWindow* window, vtkRenderer* renderer, vtkPolyDataMapper* mapper,
             vtkActor* actor, vtkCubeAxesActor* grid, const Variant& v) {
    mapper->SetInputData(v.data);
    if (v.cellColours)
        mapper->SetScalarModeToUseCellData();
    else
        mapper->SetScalarModeToUsePointData();
    actor->GetProperty()->SetLineWidth(v.lineWidth);
    grid->SetVisibility(v.grid);
    double bounds[6];
    v.data->GetBounds(bounds);
    grid->SetBounds(bounds);
    renderer->GetActiveCamera()->SetPosition(0, 0, 1);
    renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
    renderer->GetActiveCamera()->SetViewUp(0, 1, 0);
    renderer->GetActiveCamera()->Elevation(30);
    renderer->ResetCamera();
    const auto first = Clock::now();
    window->Render();
    const double firstMs = msSince(first);
    std::vector<double> times;
    for (int i = 0; i < 11; ++i) {
        renderer->GetActiveCamera()->Azimuth(5);
        renderer->ResetCameraClippingRange();
        const auto t = Clock::now();
        window->Render();
        times.push_back(msSince(t));
    }
    std::sort(times.begin(), times.end());
    std::printf("frames %-34s %8lld cells: first %7.1f ms, median %7.1f ms, max %7.1f ms\n",
                v.name.c_str(), static_cast<long long>(v.data->GetNumberOfCells()), firstMs,
                times[5], times.back());
    std::fflush(stdout);
}

void frames(const std::vector<Variant>& variants, int samples, int width, int height) {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(width, height);
    if (samples >= 0) window->SetMultiSamples(samples);  // < 0: VTK's default
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0.1, 0.1, 0.15);
    window->AddRenderer(renderer);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetColorModeToDirectScalars();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetLighting(false);
    renderer->AddActor(actor);
    vtkNew<vtkCubeAxesActor> grid;
    grid->SetCamera(renderer->GetActiveCamera());
    grid->DrawXGridlinesOn();
    grid->DrawYGridlinesOn();
    grid->DrawZGridlinesOn();
    grid->SetFlyModeToStaticEdges();
    renderer->AddActor(grid);
    std::printf("window %d x %d, %d samples\n", width, height, window->GetMultiSamples());
    for (const Variant& v : variants)
        measure(window, renderer, mapper, actor, grid, v);
    const char* capabilities = window->ReportCapabilities();
    const char* line =
        capabilities ? std::strstr(capabilities, "OpenGL renderer string:") : nullptr;
    if (line) std::printf("%.*s\n", static_cast<int>(std::strcspn(line, "\n")), line);
}

}  // namespace

int main(int argc, char** argv) {
    bool withFrames = false, canvasOnly = false, arcs = false;
    int count = 1'000'000, samples = 0, width = 1000, height = 700;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0)
            withFrames = true;
        else if (std::strcmp(argv[i], "--arcs") == 0)
            arcs = true;
        else if (std::strcmp(argv[i], "--canvas") == 0)
            withFrames = canvasOnly = true;
        else if (std::strcmp(argv[i], "--samples") == 0 && i + 1 < argc)
            samples = std::atoi(argv[++i]);
        else if (std::strcmp(argv[i], "--size") == 0 && i + 2 < argc) {
            width = std::atoi(argv[++i]);
            height = std::atoi(argv[++i]);
        } else
            count = std::atoi(argv[i]);
    }
    const double rss0 = peakRssMb();
    const auto t0 = Clock::now();
    ToolpathGeometry g = arcs ? arcHeavy(count) : million(count);
    std::printf("geometry: %zu segments in %.1f ms, %.1f MB held, peak RSS +%.1f MB\n",
                g.scene.segmentCount(), msSince(t0), g.memoryBytes() / 1e6, peakRssMb() - rss0);
    mtc::screens::ToolpathPalette palette;
    const double rss1 = peakRssMb();
    const auto t1 = Clock::now();
    auto full = mtc::screens::toolpathPolyData(g, false, palette);
    const double fullMs = msSince(t1);
    const auto t2 = Clock::now();
    const double tolerance = g.scene.bounds.size() / 1000.0;
    const DecimatedLayer decimated = decimateLayer(g, false, tolerance, 40000);
    auto coarse = mtc::screens::toolpathLevelOfDetail(g, false, palette, decimated);
    std::printf(
        "poly-data: %lld cells, %lld points in %.1f ms; coarse copy %lld cells (tolerance %.3f "
        "mm) in %.1f ms; peak RSS +%.1f MB; total peak RSS %.1f MB\n",
        static_cast<long long>(full->GetNumberOfCells()),
        static_cast<long long>(full->GetNumberOfPoints()), fullMs,
        static_cast<long long>(coarse->GetNumberOfCells()), decimated.tolerance, msSince(t2),
        peakRssMb() - rss1, peakRssMb());
    const auto t3 = Clock::now();
    auto everySegment = mtc::screens::toolpathPolyData(g, false, palette, false);
    std::printf("poly-data with every repeat (before TP-022): %lld cells in %.1f ms\n",
                static_cast<long long>(everySegment->GetNumberOfCells()), msSince(t3));
    std::fflush(stdout);
    if (!withFrames) return 0;
    if (canvasOnly) {  // what the view draws: still frame, then while moving
        // and the full path with every repeat drawn (before TP-022), side by side
        frames(
            {{"full, point colours, width 1, grid", full, false, 1.0f, true},
             {"coarse, point colours, width 1, grid", coarse, false, 1.0f, true},
             {"full with repeats, point colours, width 1, grid", everySegment, false, 1.0f, true}},
            samples, width, height);
        std::printf("total peak RSS %.1f MB\n", peakRssMb());
        return 0;
    }
    // The old drawings had a cell per segment (cell i = segment i).
    auto cells =
        withCellColours(mtc::screens::toolpathPolyData(g, false, palette, false), g, palette);
    frames({{"full, cell colours, width 1", cells, true, 1.0f, false},
            {"full, cell colours, width 1.5", cells, true, 1.5f, false},
            {"full, point colours, width 1", full, false, 1.0f, false},
            {"full, point colours, width 1.5", full, false, 1.5f, false},
            {"full, point colours, width 1, grid", full, false, 1.0f, true},
            {"coarse, point colours, width 1", coarse, false, 1.0f, false},
            {"coarse, point colours, width 1, grid", coarse, false, 1.0f, true},
            {"coarse, point colours, width 1.5", coarse, false, 1.5f, false}},
           samples, width, height);
    std::printf("total peak RSS %.1f MB\n", peakRssMb());
    return 0;
}
