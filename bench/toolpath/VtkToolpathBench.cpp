// VTK part of the toolpath view (issue 8), outside ctest:
//   mtc_toolpath_bench            poly-data build for 1,000,000 segments
//   xvfb-run -a -s "-screen 0 1280x1024x24" mtc_toolpath_bench --frames
//                                 frame times of a 1000x700 X window (Mesa
//                                 llvmpipe under Xvfb): full path and the
//                                 level-of-detail copy shown while moving.
// Output: one line per measurement (ms, MB of the process's peak RSS growth).
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <sys/resource.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "cnc_core/machine/MachineConfigReader.h"
#include "cnc_core/toolpath/ToolpathBuilder.h"
#include "resources/EmbeddedResources.h"
#include "screens/toolpath/ToolpathPalette.h"
#include "screens/toolpath/VtkToolpathData.h"

namespace {

using namespace mtc::core;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double peakRssMb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

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

void frames(vtkPolyData* full, vtkPolyData* coarse) {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(1000, 700);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetScalarModeToUseCellData();
    mapper->SetColorModeToDirectScalars();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
    for (vtkPolyData* data : {full, coarse}) {
        mapper->SetInputData(data);
        renderer->ResetCamera();
        auto first = Clock::now();
        window->Render();
        const double firstMs = msSince(first);
        std::printf("first frame %.1f ms\n", firstMs);
        std::fflush(stdout);
        std::vector<double> times;
        for (int i = 0; i < 10; ++i) {
            renderer->GetActiveCamera()->Azimuth(5);
            auto t = Clock::now();
            window->Render();
            times.push_back(msSince(t));
            std::fflush(stdout);
        }
        std::sort(times.begin(), times.end());
        std::printf("frames %s (%lld cells): first %.1f ms, median %.1f ms, max %.1f ms\n",
                    data == full ? "full" : "level of detail",
                    static_cast<long long>(data->GetNumberOfCells()), firstMs, times[5],
                    times.back());
    }
    const char* capabilities = window->ReportCapabilities();
    const char* line =
        capabilities ? std::strstr(capabilities, "OpenGL renderer string:") : nullptr;
    if (line) std::printf("%.*s\n", static_cast<int>(std::strcspn(line, "\n")), line);
}

}  // namespace

int main(int argc, char** argv) {
    const bool withFrames = argc > 1 && std::strcmp(argv[1], "--frames") == 0;
    const double rss0 = peakRssMb();
    auto t0 = Clock::now();
    const int count = argc > 2 ? std::atoi(argv[2]) : 1'000'000;
    ToolpathGeometry g = million(count);
    std::printf("geometry: %zu segments in %.1f ms, %.1f MB held, peak RSS +%.1f MB\n",
                g.scene.segmentCount(), msSince(t0), g.memoryBytes() / 1e6, peakRssMb() - rss0);
    mtc::screens::ToolpathPalette palette;
    const double rss1 = peakRssMb();
    auto t1 = Clock::now();
    auto full = mtc::screens::toolpathPolyData(g, false, palette);
    const double fullMs = msSince(t1);
    auto t2 = Clock::now();
    auto coarse = mtc::screens::toolpathLevelOfDetail(g, false, palette, 150000, full->GetPoints());
    std::printf(
        "poly-data: %lld cells in %.1f ms; level of detail %lld cells in %.1f ms; "
        "peak RSS +%.1f MB; total peak RSS %.1f MB\n",
        static_cast<long long>(full->GetNumberOfCells()), fullMs,
        static_cast<long long>(coarse->GetNumberOfCells()), msSince(t2), peakRssMb() - rss1,
        peakRssMb());
    std::fflush(stdout);
    if (withFrames) frames(full, coarse);
    return 0;
}
