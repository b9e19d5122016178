// The motion planner's frame path (MOT-025) against its general path: the
// same result, diagnostics and plan (bit for bit) for random blocks over
// random modal states — units, diameter programming, incremental, zero
// offsets, planes (G17..G19, G20), G31/G32, G95, feeds, positions beyond the
// travel limits, arcs on and off their circle, repeated axes — with one
// planner of each kind kept over the whole run, so that the frame is built,
// reused and rebuilt as the states change.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <random>

#include "InterpTestSupport.h"
#include "cnc_core/interp/MotionPlanner.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

/// A turning centre with G20 alternates, a rotary axis that may take
/// definition Y (arcs in a plane with a rotary axis) and spindles.
const char* const kTurningCentre = R"(
[cell]
name = turning centre
[process 0]
name = turning centre
B004 = 18
[process 0 axis X1]
definition = X
min = -100
max = 300
[process 0 axis X2]
definition = W, X, Y, Z
[process 0 axis Y]
definition = Y, X, Z
min = -80
max = 80
[process 0 axis Z]
definition = Z, X, Y
[process 0 axis C]
kind = rotary
definition = C, Y
[process 0 axis B]
kind = rotary
definition = B
[process 0 spindle S1]
index = 1
[process 0 zero-offsets]
G54 = X10.5 Y-3.25 Z100
G57 = X-1 W2 C30
)";

class PlannerPair {
  public:
    PlannerPair(const ProcessConfig& config, std::uint32_t seed)
        : config_(config),
          axes_(ProcessAxes::build(config, diagnostics_)),
          offsets_(ZeroOffsetTable::build(config, diagnostics_)),
          framed_(&axes_, &offsets_),
          general_(&axes_, &offsets_),
          random_(seed) {
        ProgramStore store;
        NullSink sink;
        Interpreter interpreter(config, store, sink);
        modal_ = interpreter.state().modal;
    }

    /// Plans `blocks` random blocks with both planners; the states go on
    /// from the accepted plans.
    void run(int blocks) {
        for (int i = 0; i < blocks; ++i)
            step();
    }
    std::map<std::string, int> outcomes;

  private:
    double uniform(double low, double high) {
        return std::uniform_real_distribution<double>(low, high)(random_);
    }
    int pick(int count) { return std::uniform_int_distribution<int>(0, count - 1)(random_); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

    /// The programmed value that takes `axis` to the work coordinate
    /// `target` (from `from` under G91): programmedValue() inverted.
    double programmed(int axis, double target, double from) const;
    void changeModal();
    void changeGeometry();
    BlockInput randomBlock();
    void step();

    const ProcessConfig& config_;
    DiagnosticList diagnostics_;
    ProcessAxes axes_;
    ZeroOffsetTable offsets_;
    MotionPlanner framed_, general_;
    std::mt19937 random_;
    ModalState modal_;
    ProgramPtr program_ = parse("N0001 G1 X0\n", 1);
};

void PlannerPair::changeModal() {
    if (chance(0.05)) modal_.g[kGroupUnits] = static_cast<std::int16_t>(chance(0.5) ? 70 : 71);
    if (chance(0.05))
        modal_.g[kGroupRadiusDiameter] = static_cast<std::int16_t>(chance(0.5) ? 15 : 16);
    if (chance(0.1)) modal_.g[kGroupDimension] = static_cast<std::int16_t>(chance(0.7) ? 90 : 91);
    if (chance(0.05)) modal_.g[kGroupZeroOffset] = static_cast<std::int16_t>(53 + pick(7));
    if (chance(0.3)) modal_.g[kGroupInterpolation] = static_cast<std::int16_t>(pick(4));
    if (chance(0.03)) modal_.g[kGroupFeedType] = static_cast<std::int16_t>(chance(0.3) ? 95 : 94);
    if (chance(0.1)) {
        const double feeds[] = {0.0, 0.0005, 0.001, 0.2, 1000.0, 1250.5, 60000.0, -5.0};
        modal_.feed = feeds[pick(8)];
    }
    if (chance(0.05)) modal_.spindleSpeed[1] = chance(0.3) ? 0.0 : uniform(10.0, 3000.0);
    if (chance(0.01))
        (void)offsets_.set(54 + pick(6), AxisDefinition(pick(kDefinitionCount)),
                           uniform(-50.0, 50.0));  // operator input
    changeGeometry();
}

void PlannerPair::changeGeometry() {
    if (chance(0.03)) (void)modal_.plane.selectStandard(axes_, 17 + pick(3));
    if (chance(0.03)) {
        std::vector<FreePlaneAxis> free;
        for (int n = 2 + pick(2); n > 0; --n)
            free.push_back({pick(axes_.count()), 0.0, 1});
        (void)modal_.plane.selectFree(axes_, free);
    }
    if (chance(0.02)) modal_.transformation.deselect();
    if (chance(0.01))
        (void)modal_.transformation.selectCylinder(axes_, modal_.plane, true, uniform(5.0, 50.0));
    if (chance(0.01)) (void)modal_.transformation.selectFacing(axes_, modal_.plane);
    if (chance(0.02))
        for (int a = 0; a < axes_.count(); ++a) {
            modal_.work[static_cast<size_t>(a)] = uniform(-50.0, 50.0);
            modal_.machine[static_cast<size_t>(a)] = uniform(-50.0, 50.0);
        }
}

double PlannerPair::programmed(int axis, double target, double from) const {
    double value = modal_.g[kGroupDimension] == 91 ? target - from : target;
    if (axes_.axis(axis).rotary && !modal_.transformation.transforms(axis)) return value;
    if (modal_.g[kGroupUnits] == 70) value /= 25.4;
    if (modal_.g[kGroupRadiusDiameter] == 16 &&
        modal_.plane.definitionOf(axis) == AxisDefinition::X)
        value *= 2.0;
    return value;
}

BlockInput PlannerPair::randomBlock() {
    BlockInput in;
    in.clear();
    for (int a = 0; a < axes_.count(); ++a) {
        if (!chance(0.4)) continue;
        const double target = chance(0.03) ? uniform(-500.0, 500.0) : uniform(-40.0, 40.0);
        const double v = programmed(a, target, modal_.work[static_cast<size_t>(a)]);
        in.axisMask = static_cast<std::uint16_t>(in.axisMask | (1u << a));
        in.axisValue[static_cast<size_t>(a)] = v;
        in.axisColumn[static_cast<size_t>(a)] = static_cast<std::uint16_t>(3 + a);
        in.axisOrder[static_cast<size_t>(in.axisCount)] = static_cast<std::uint8_t>(a);
        in.orderValue[static_cast<size_t>(in.axisCount++)] = v;
    }
    if (in.axisMask == 0) {
        in.axisMask = 1;
        in.axisValue[0] = uniform(-60.0, 60.0);
        in.axisOrder[0] = 0;
        in.axisCount = 1;
    }
    if (chance(0.01)) in.repeatedAxisColumn = 7;
    const int p1 = modal_.plane.firstAxis(), p2 = modal_.plane.secondAxis();
    in.centerMask = static_cast<std::uint8_t>(pick(8));
    if (p1 >= 0 && p2 >= 0 && chance(0.8)) {  // the centre words of the plane's axes
        in.centerMask = 0;
        for (const int axis : {p1, p2}) {
            const auto definition = static_cast<int>(modal_.plane.definitionOf(axis));
            if (definition >= 0 && definition < 3)
                in.centerMask = static_cast<std::uint8_t>(in.centerMask | (1u << definition));
        }
    }
    in.centerColumn = 20;
    if (p1 >= 0 && p2 >= 0 && chance(0.8)) {
        // An end on the circle around a random centre (G90 G71 G15 work units).
        const double c1 = modal_.work[static_cast<size_t>(p1)] + uniform(-20.0, 20.0);
        const double c2 = modal_.work[static_cast<size_t>(p2)] + uniform(-20.0, 20.0);
        const double r = std::hypot(modal_.work[static_cast<size_t>(p1)] - c1,
                                    modal_.work[static_cast<size_t>(p2)] - c2);
        const double angle = chance(0.05) ? 0.0 : uniform(-3.0, 3.0);
        in.axisMask = static_cast<std::uint16_t>(in.axisMask | (1u << p1) | (1u << p2));
        const double s1 = modal_.work[static_cast<size_t>(p1)];
        const double s2 = modal_.work[static_cast<size_t>(p2)];
        in.axisValue[static_cast<size_t>(p1)] = programmed(p1, c1 + r * std::cos(angle), s1);
        in.axisValue[static_cast<size_t>(p2)] = programmed(p2, c2 + r * std::sin(angle), s2);
        in.axisCount = 0;
        for (int a = 0; a < axes_.count(); ++a)
            if ((in.axisMask >> a) & 1u)
                in.axisOrder[static_cast<size_t>(in.axisCount++)] = static_cast<std::uint8_t>(a);
        in.center = {uniform(-30.0, 30.0), uniform(-30.0, 30.0), uniform(-30.0, 30.0)};
        const int d1 = static_cast<int>(modal_.plane.definitionOf(p1));
        const int d2 = static_cast<int>(modal_.plane.definitionOf(p2));
        if (d1 >= 0 && d1 < 3) in.center[static_cast<size_t>(d1)] = programmed(p1, c1, s1);
        if (d2 >= 0 && d2 < 3) in.center[static_cast<size_t>(d2)] = programmed(p2, c2, s2);
    } else {
        in.center = {uniform(-30.0, 30.0), uniform(-30.0, 30.0), uniform(-30.0, 30.0)};
    }
    return in;
}

void PlannerPair::step() {
    changeModal();
    const BlockInput in = randomBlock();
    BlockPlan a, b;
    assignModalState(a.next, modal_);
    assignModalState(b.next, modal_);
    DiagnosticList da, db;
    const bool okA = framed_.plan({*program_, 0, da}, in, modal_, a, PlanningOptions{0.002, true});
    const bool okB =
        general_.plan({*program_, 0, db}, in, modal_, b, PlanningOptions{0.002, false});
    ASSERT_EQ(okA, okB);
    ASSERT_EQ(diagnosticsText(da), diagnosticsText(db));
    const std::string outcome =
        okA ? "ok G" + std::to_string(modal_.g[kGroupInterpolation]) : errorCodes(da).front();
    ++outcomes[outcome];
    if (!okA) return;  // a refused block's plan is discarded
    // Bit for bit on purpose (-0.0 against 0.0 counts); both plans start as
    // copies of the same state, so their padding bytes are equal too.
    // NOLINTNEXTLINE(bugprone-suspicious-memory-comparison)
    ASSERT_EQ(std::memcmp(&a.next, &b.next, sizeof(ModalState)), 0) << outcome;
    ASSERT_EQ(a.hasMotion, b.hasMotion);
    ASSERT_EQ(a.motionType, b.motionType);
    ASSERT_EQ(a.planeAxis1, b.planeAxis1);
    ASSERT_EQ(a.planeAxis2, b.planeAxis2);
    ASSERT_EQ(a.fullCircle, b.fullCircle);
    const double fa[] = {a.center1, a.center2, a.planeCenter1, a.planeCenter2, a.feedRate};
    const double fb[] = {b.center1, b.center2, b.planeCenter1, b.planeCenter2, b.feedRate};
    // NOLINTNEXTLINE(bugprone-suspicious-memory-comparison): bit for bit, as above
    ASSERT_EQ(std::memcmp(fa, fb, sizeof fa), 0) << outcome;
    assignModalState(modal_, a.next);
}

void expectBothPathsAgree(const ProcessConfig& config, std::uint32_t seed) {
    PlannerPair pair(config, seed);
    pair.run(40000);
    if (::testing::Test::HasFatalFailure()) return;
    // The run reaches every kind of move and the refusals the frame path
    // gives itself (TRAVEL_LIMIT, the radii, the feed).
    for (const char* outcome : {"ok G0", "ok G1", "ok G2", "ok G3", "FEED_MISSING"})
        EXPECT_GT(pair.outcomes[outcome], 20) << outcome;
    std::string seen;
    for (const auto& [outcome, count] : pair.outcomes)
        seen += outcome + " " + std::to_string(count) + "\n";
    SCOPED_TRACE(seen);
    EXPECT_GT(pair.outcomes["TRAVEL_LIMIT"] + pair.outcomes["ARC_RADIUS_MISMATCH"], 20);
}

TEST(MotionPlannerFrame, AgreesWithTheGeneralPathOnTheMill) {
    expectBothPathsAgree(*demoCell().process(0), 1);
}

TEST(MotionPlannerFrame, AgreesWithTheGeneralPathOnTheLathe) {
    expectBothPathsAgree(*demoCell().process(1), 2);
}

TEST(MotionPlannerFrame, AgreesWithTheGeneralPathOnATurningCentre) {
    static const MachineConfig cell = cellFromText(kTurningCentre);
    expectBothPathsAgree(*cell.process(0), 3);
}

}  // namespace
