// No programmed number makes the toolpath's tessellation grow without bound
// (issue 15 §1, TP-004): an arc of a huge radius, a NaN sweep, a G32 line
// over millions of turns get at most kMaxArcChords chords.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "InterpTestSupport.h"
#include "cnc_core/toolpath/CurveMath.h"
#include "cnc_core/toolpath/ToolpathRun.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

TEST(ToolpathLimits, ChordCountsAreBoundedForAnyNumber) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const int cap = static_cast<int>(curve::kMaxArcChords);
    for (double radius : {1e-300, 1.0, 1e6, 1e15, 1e300, inf, nan})
        for (double sweep : {1e-300, 0.5, 2 * curve::kPi, 1e6, 1e300, inf, nan})
            for (double tolerance : {0.01, 1e-300, 0.0, nan}) {
                const int chords = curve::arcChords(radius, sweep, tolerance);
                EXPECT_GE(chords, 1) << radius << " " << sweep << " " << tolerance;
                EXPECT_LE(chords, cap) << radius << " " << sweep << " " << tolerance;
            }
    // ordinary arcs keep their tolerance: no cap reached
    EXPECT_EQ(curve::arcChords(100.0, 2 * curve::kPi, 0.01),
              static_cast<int>(std::ceil(2 * curve::kPi / (2 * std::acos(1 - 0.01 / 100.0)))));
}

TEST(ToolpathLimits, HugeArcsAndWrapsAreBounded) {
    // demo lathe (process 1): under G32 a developed move of 1e9 mm on RI 36.5
    // turns the cylinder 4.4 million times
    const char* program =
        "N0001 G0 X45 Z100\nN0002 M5\nN0003 G0 C0\nN0004 G20 Z0 C0 X0\nN0005 G32 RI 36.5\n"
        "N0006 G0 G56 Y1 0 Z1 100\nN0007 G1 X34.5 F120\nN0008 G1 Y1 1000000000 F300\n"
        "N0009 G30\nN0010 M30\n";
    ProgramStore store;
    store.put(1, 1, parse(program, 1));
    const ToolpathRunResult r = buildToolpath(demoCell().processes[1], store, 1);
    EXPECT_LE(r.geometry.scene.segmentCount(), 10u * 65536u) << diagnosticsText(r.diagnostics);
}

}  // namespace
