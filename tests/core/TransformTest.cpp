// Transformations G30/G31/G32 (seed 003, ch. 4 and 5.2/5.3): arc length to
// angle through RI, direction of rotation Cxx.076, polar coordinates for
// facing, the changes on selection and deselection, axis designation 2.
#include <gtest/gtest.h>

#include <cmath>

#include "InterpTestSupport.h"
#include "cnc_core/machine/Transformation.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;

constexpr double kPi = 3.14159265358979323846;

/// A lathe like the demo lathe but with the zero offsets of seed 003, 6.3
/// (G54 Z 267.85 for turning, G55 X 267.85 for the lateral cylinder, where
/// the Z axis has definition X), diameter programming by default, and the
/// polar directions given as parameters.
std::string lathe(int rotaryDirection, int linearDirection, const char* b015 = "diameter") {
    return std::string(R"(
[cell]
name = transform lathe
[process 0]
name = lathe
B004 = 18
B015 = )") +
           b015 + R"(
[process 0 axis X]
definition = X, Z
designation2 = X1
polar_direction = )" +
           std::to_string(linearDirection) + R"(
min = -100
max = 300
[process 0 axis Z]
definition = Z, X
designation2 = Z1
min = -100
max = 700
[process 0 spindle S1]
index = 1
rotary_axis = C
definition = C, Y
designation2 = Y1
polar_direction = )" +
           std::to_string(rotaryDirection) + R"(
[process 0 axis Y]
definition = Y
min = -60
max = 60
[process 0 tools]
T7 = radius 4.85 length 70
[process 0 zero-offsets]
G54 = Z267.85
G55 = X267.85
)";
}

struct Lathe {
    explicit Lathe(int rotaryDirection = 0, int linearDirection = 0, const char* b015 = "diameter")
        : cell(cellFromText(lathe(rotaryDirection, linearDirection, b015))), station(cell, 0) {}
    const ModalState& modal() const { return station.interpreter->state().modal; }
    double machine(int axis) const { return modal().machine[static_cast<size_t>(axis)]; }
    MachineConfig cell;
    Station station;
};

constexpr int X = 0, Z = 1, C = 2;

TEST(TransformCylinder, ArcLengthBecomesAngleThroughRi) {
    DiagnosticList d;
    const MachineConfig cell = cellFromText(lathe(0, 0));
    const ProcessAxes axes = ProcessAxes::build(*cell.process(0), d);
    PlaneSelection plane = PlaneSelection::base(axes, 18);
    ASSERT_TRUE(plane.selectFree(axes, {{Z, 0, 1}, {C, 0, 2}, {X, 0, 3}}).empty());
    Transformation t;
    ASSERT_TRUE(t.selectCylinder(axes, plane, true, 36.5).empty());
    double m1 = 0, m2 = 0;
    t.toMachine(axes, -36.15, 25.0, 0, 0, m1, m2);
    EXPECT_DOUBLE_EQ(m1, -36.15) << "the linear axis is not converted";
    EXPECT_NEAR(m2, 25.0 / 36.5 * 180.0 / kPi, 1e-12);
    double c1 = 0, c2 = 0;
    t.toPlane(axes, m1, m2, c1, c2);
    EXPECT_NEAR(c2, 25.0, 1e-12);
    // The unit radius n / (2 pi): the surface distance equals the angle.
    Transformation unit;
    ASSERT_TRUE(unit.selectCylinder(axes, plane, true, 360.0 / (2 * kPi)).empty());
    unit.toMachine(axes, 0, 90.0, 0, 0, m1, m2);
    EXPECT_NEAR(m2, 90.0, 1e-9);
}

TEST(TransformCylinder, DirectionParameterReversesTheRotation) {
    Lathe normal(0), reversed(1);
    const std::string program = "N1 G0 X80 Z50 C0\nN2 G20 Z0 C0 X0\nN3 G32 RI 40\nN4 G0 Y1 10\n";
    normal.station.run(program);
    reversed.station.run(program);
    const double angle = 10.0 / 40.0 * 180.0 / kPi;
    EXPECT_NEAR(normal.machine(C), angle, 1e-9);
    EXPECT_NEAR(reversed.machine(C), -angle, 1e-9);
}

TEST(TransformCylinder, SelectionSetsG53AndRadiusProgrammingDeselectionRestores) {
    Lathe l;  // B015 = diameter: G16 is the default
    RunResult r = l.station.run(
        "N1 G54 G0 X160 Z-20 C0\n"  // diameter 160 -> X 80; Z -20 + 267.85
        "N2 @1=G(4) @2=G(7)\n"
        "N3 G20 Z0 C0 X0\n"
        "N4 G32 RI 36.5\n"
        "N5 @3=G(4) @4=G(7)\n"
        "N6 G55 G0 Z1 -36.15 Y1 25\n"  // G55 column X belongs to Z (definition X now)
        "N7 X38\n"                     // X is the perpendicular axis: radius programming
        "N8 G30\n"
        "N9 @5=G(4) @6=G(7) @7=G(17)\n"
        "N10 M0\n");
    ASSERT_EQ(r.status, RunStatus::Stopped) << diagnosticsText(r.diagnostics);
    const auto& v = l.station.interpreter->state().variables.values;
    EXPECT_EQ(v[1], 54);
    EXPECT_EQ(v[2], 16);
    EXPECT_EQ(v[3], 53) << "G32 sets G53";
    EXPECT_EQ(v[4], 15) << "radius programming while G32 is active";
    EXPECT_EQ(v[5], 53) << "G30 sets G53";
    EXPECT_EQ(v[6], 16) << "G30 restores the default of B015";
    EXPECT_EQ(v[7], 30);
    EXPECT_NEAR(l.machine(Z), -36.15 + 267.85, 1e-9);
    EXPECT_NEAR(l.machine(X), 38.0, 1e-9);
    EXPECT_NEAR(l.machine(C), 25.0 / 36.5 * 180.0 / kPi, 1e-9);
}

TEST(TransformCylinder, DiameterProgrammingDuringG32AppliesToTheAxisWithDefinitionX) {
    Lathe l;
    l.station.run("N1 G0 X100 Z40 C0\nN2 G20 Z0 C0 X0\nN3 G32 RI 30\nN4 G16 G0 Z1 50 X60\nN5 M0\n");
    EXPECT_NEAR(l.machine(Z), 25.0, 1e-9) << "Z has definition X: its values are diameters";
    EXPECT_NEAR(l.machine(X), 60.0, 1e-9) << "X has definition Z: not converted";
}

TEST(TransformCylinder, RiCannotChangeUntilG30) {
    Lathe l;
    RunResult r = l.station.run(
        "N1 G0 X80 Z0 C0\nN2 G20 Z0 C0 X0\nN3 G32 RI 30\nN4 G32 RI 31\nN5 G30\nN6 G32 RI 31\nN7 "
        "M0\n");
    EXPECT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"G32_RI_CHANGE"});
}

TEST(TransformCylinder, DesignationTwoOnlyWhileActive) {
    Lathe l;
    l.station.interpreter->options().continueAfterError = true;
    RunResult r = l.station.run(
        "N1 G0 X80 Z0 C0\nN2 Z1 5\nN3 G20 Z0 C0 X0 G32 RI 30\nN4 G0 Z1 5 Y1 3\nN5 C20\n"
        "N6 G30\nN7 Y1 3\nN8 G0 C20\nN9 M30\n");
    EXPECT_EQ(errorCodes(r.diagnostics),
              (std::vector<std::string>{"AXIS_DESIGNATION2_INACTIVE", "AXIS_TRANSFORMED",
                                        "AXIS_DESIGNATION2_INACTIVE"}));
}

TEST(TransformCylinder, ProgramEndAndJmpDeselect) {
    Lathe l;
    l.station.add("N1 @1=G(17) @2=G(2)\nN2 M30\n", 2);
    l.station.run("N1 G0 X80 Z0 C0\nN2 G20 Z0 C0 X0\nN3 G32 RI 30\nN4 JMP 2\n");
    const auto& v = l.station.interpreter->state().variables.values;
    EXPECT_EQ(v[1], 30) << "JMP ends the program: G32 off";
    EXPECT_EQ(v[2], 18) << "and the base plane is back";
    EXPECT_EQ(l.modal().transformation.kind(), 30);
}

TEST(TransformCylinder, RiIsInInchUnderG70) {
    // Regression: RI was taken in mm under G70, so the angle came out 25.4
    // times too large. RI 1 inch = 25.4 mm; 1 inch on the shell = 1 radian.
    Lathe l;
    const RunResult r =
        l.station.run("N1 G0 X80 Z50 C0\nN2 G70 G20 Z0 C0 X0\nN3 G32 RI 1\nN4 G0 Y1 1\nN5 M0\n");
    ASSERT_EQ(r.status, RunStatus::Stopped) << diagnosticsText(r.diagnostics);
    EXPECT_NEAR(l.machine(C), 180.0 / kPi, 1e-9);
    EXPECT_DOUBLE_EQ(l.modal().transformation.effectiveRadius(), 25.4);
    EXPECT_NEAR(l.station.interpreter->programmedPosition(C), 1.0, 1e-12);  // inch again
    // The same RI written again under G70 is no change of RI.
    EXPECT_EQ(l.station.run("N1 G32 RI 1\nN2 M0\n", 2).status, RunStatus::Stopped);
}

TEST(TransformCylinder, ProgramsNameTheTransformedAxesByDesignationTwo) {
    Lathe l;
    l.station.run("N1 G0 X80 Z50 C0\nN2 G20 Z0 C0 X0\nN3 G32 RI 30\nN4 G0 Y1 25\nN5 M0\n");
    const Interpreter& interpreter = *l.station.interpreter;
    EXPECT_EQ(interpreter.programmedAxisName(C), "Y1");
    EXPECT_EQ(interpreter.programmedAxisName(Z), "Z1");
    EXPECT_EQ(interpreter.programmedAxisName(X), "X") << "the infeed axis keeps its name";
    EXPECT_EQ(interpreter.axisName(C), "C") << "designation 1 of the machine axis";
    l.station.run("N1 G30\nN2 M0\n", 2);
    EXPECT_EQ(interpreter.programmedAxisName(C), "C");
}

TEST(TransformCylinder, FeedPerRevolutionIsRefusedForARotaryAxisWithDefinitionXYZ) {
    // Seed 003, 3.6: every axis can move with G95 except a rotary axis with
    // definition X, Y or Z. Regression: accepted.
    Lathe l;
    RunResult r = l.station.run(
        "N1 G0 X80 Z50 C0\nN2 S1000 M3\nN3 G20 Z0 C0 X0\nN4 G32 RI 30\nN5 G95 G1 Y1 5 "
        "F0.1\n");
    EXPECT_EQ(errorCodes(r.diagnostics), std::vector<std::string>{"G95_ROTARY_AXIS"});
    EXPECT_NEAR(l.machine(C), 0.0, 1e-12) << "nothing moved";
    Lathe linear;  // the linear axes of the same plane may
    r = linear.station.run("N1 G0 X80 Z50 C0\nN2 S1000 M3\nN3 G95 G1 Z40 F0.1\nN4 M0\n");
    EXPECT_EQ(r.status, RunStatus::Stopped) << diagnosticsText(r.diagnostics);
}

TEST(TransformFacing, PolarCoordinates) {
    DiagnosticList d;
    const MachineConfig cell = cellFromText(lathe(0, 0));
    const ProcessAxes axes = ProcessAxes::build(*cell.process(0), d);
    PlaneSelection plane = PlaneSelection::base(axes, 18);
    ASSERT_TRUE(plane.selectFree(axes, {{X, 0, 1}, {C, 0, 2}, {Z, 0, 3}}).empty());
    Transformation t;
    ASSERT_TRUE(t.selectFacing(axes, plane).empty());
    double r = 0, a = 0;
    t.toMachine(axes, 0.0, 30.0, 50.0, 350.0, r, a);
    EXPECT_NEAR(r, 30.0, 1e-12);
    EXPECT_NEAR(a, 450.0, 1e-9) << "90 degrees, on the turn nearest to 350";
    t.toMachine(axes, 0.0, 0.0, 30.0, 123.0, r, a);
    EXPECT_NEAR(a, 123.0, 1e-12) << "at the rotation centre the angle stays";
    double x = 0, y = 0;
    t.toPlane(axes, 30.0, 450.0, x, y);
    EXPECT_NEAR(x, 0.0, 1e-9);
    EXPECT_NEAR(y, 30.0, 1e-9);
}

TEST(TransformFacing, DirectionParametersOfRotaryAndLinearAxis) {
    DiagnosticList d;
    for (int rotary : {0, 1})
        for (int linear : {0, 1}) {
            const MachineConfig cell = cellFromText(lathe(rotary, linear));
            const ProcessAxes axes = ProcessAxes::build(*cell.process(0), d);
            PlaneSelection plane = PlaneSelection::base(axes, 18);
            ASSERT_TRUE(plane.selectFree(axes, {{X, 0, 1}, {C, 0, 2}, {Z, 0, 3}}).empty());
            Transformation t;
            ASSERT_TRUE(t.selectFacing(axes, plane).empty());
            double r = 0, a = 0, x = 0, y = 0;
            t.toMachine(axes, 10.0, 10.0, 0.0, 0.0, r, a);
            const double expectedAngle = (linear ? 225.0 : 45.0) * (rotary ? -1.0 : 1.0);
            EXPECT_NEAR(r, linear ? -std::sqrt(200.0) : std::sqrt(200.0), 1e-9);
            EXPECT_NEAR(nearestTurn(a, expectedAngle), expectedAngle, 1e-9)
                << "rotary " << rotary << " linear " << linear;
            t.toPlane(axes, r, a, x, y);
            EXPECT_NEAR(x, 10.0, 1e-9);
            EXPECT_NEAR(y, 10.0, 1e-9);
        }
}

TEST(Transform, NearestTurn) {
    EXPECT_DOUBLE_EQ(nearestTurn(10.0, 355.0), 370.0);
    EXPECT_DOUBLE_EQ(nearestTurn(-90.0, 0.0), -90.0);
    EXPECT_DOUBLE_EQ(nearestTurn(180.0, -170.0), -180.0);
}

}  // namespace
