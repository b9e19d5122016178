// Material removal: the input is an NC program, run on the mill or the lathe
// of the demo cell (by the input's length) into the part model at a coarse
// resolution, bounded by a block budget. The stock makes a part (or an
// error about the program's window says why not). The part stays inside
// its stock (heights between bottom and top, radii between 0 and the
// bar's, on the G32 jacket too), the removed volume is finite and at most
// the stock's, diagnostics have a code, and the STL has the size its
// triangle count promises.
#include <algorithm>
#include <cmath>
#include <string>

#include "../FuzzTargets.h"
#include "DemoCell.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/removal/PartStl.h"
#include "cnc_core/removal/RemovalRun.h"

namespace mtc::fuzz {

namespace {

void checkHeightField(const core::removal::HeightField& f, std::string_view input) {
    const core::removal::Box& box = f.stock();
    for (int j = 0; j < f.rows(); ++j)
        for (int i = 0; i < f.columns(); ++i) {
            const double h = f.height(i, j);
            require(h >= static_cast<float>(box.min[2]) && h <= static_cast<float>(box.max[2]),
                    "a height lies between the stock's bottom and top", input);
        }
}

void checkProfile(const core::removal::TurnedProfile& p, std::string_view input) {
    for (int k = 0; k < p.slices(); ++k)
        require(p.radiusAt(k) >= 0.0 && p.radiusAt(k) <= p.stockRadius(),
                "a radius lies between 0 and the bar's", input);
}

/// The jacket of the G32 cuts (D-027): one row per slice, every radius
/// between 0 and the bar's, its volume finite and within what was removed.
void checkJacket(const core::removal::PartModel& part, std::string_view input) {
    const core::removal::DevelopedSurface* jacket = part.jacket();
    if (jacket == nullptr) return;
    const core::removal::TurnedProfile& p = *part.profile();
    require(jacket->rows() == p.slices(), "the jacket has a row per slice", input);
    for (int j = 0; j < jacket->rows(); ++j)
        for (int i = 0; i < jacket->columns(); ++i)
            require(jacket->radius(i, j) >= 0.0 &&
                        jacket->radius(i, j) <= static_cast<float>(p.stockRadius()),
                    "a jacket radius lies between 0 and the bar's", input);
    const double developed = part.developedVolume();
    require(std::isfinite(developed) && developed >= 0.0 &&
                developed <= part.removedVolume() * (1.0 + 1e-9),
            "the developed volume is finite and part of the removed volume", input);
}

}  // namespace

void fuzzRemoval(std::string_view input) {
    const int process = static_cast<int>(input.size() % 2);
    core::ParseOptions options;
    options.programNumber = 1;
    auto program = std::make_shared<core::Program>(core::parseProgram(std::string(input), options));
    program->number = 1;
    core::ProgramStore store;
    store.put(process, 1, program);
    core::removal::RemovalSettings settings;
    settings.resolution = 2.0;  // coarse: the fuzzer's executions stay fast
    const core::removal::RemovalRunResult r = core::removal::simulateRemoval(
        *demoCell().process(process), store, 1, settings, nullptr, 5'000);
    for (const core::Diagnostic& d : r.diagnostics.items())
        require(!d.code.empty() && !d.message.empty(), "a diagnostic has code and message", input);
    if (!r.part) {
        // The program's window is the stock (TP-008): one the model cannot
        // hold (a WINDOW_01 bar on the mill, a bad window or RAW contour)
        // makes no part, and an error at the window says why.
        require(std::any_of(r.diagnostics.items().begin(), r.diagnostics.items().end(),
                            [](const core::Diagnostic& d) {
                                return d.severity == core::Severity::Error &&
                                       (d.code == "REMOVAL_STOCK" || d.code == "REMOVAL_WINDOW" ||
                                        d.code == "REMOVAL_RAW_CONTOUR");
                            }),
                "the demo cell's stock makes a part, or an error says why not", input);
        return;
    }
    const core::removal::PartModel& part = *r.part;
    const double removed = part.removedVolume();
    require(std::isfinite(removed) && removed >= 0.0, "the removed volume is finite", input);
    if (const core::removal::HeightField* f = part.heightField()) {
        checkHeightField(*f, input);
    } else {
        checkProfile(*part.profile(), input);
        checkJacket(part, input);
    }
    require(r.counts.cuttingMoves <= r.counts.moves, "only moves cut", input);
    const std::string stl = core::removal::partStl(part);
    require(stl.size() == 84 + 50 * core::removal::stlTriangleCount(part),
            "the STL holds its triangles", input);
}

}  // namespace mtc::fuzz
