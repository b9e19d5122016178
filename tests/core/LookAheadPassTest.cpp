// The look-ahead compiler pass: object program, numerical check of the
// written blocks, TRC in the object, and every error condition.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/lookahead/LookAheadPass.h"
#include "cnc_core/compiler/lookahead/VelocityProfileExport.h"
#include "tests/core/CompilerTestSupport.h"
#include "tests/core/LookAheadObjectCheck.h"
#include "tests/core/LookAheadTestSupport.h"

using namespace mtc::core;
using namespace mtc::core::lookahead;
using namespace mtc::core::lookahead::testing;

namespace {

ProcessConfig millProcess() {
    ProcessConfig p;
    p.name = "Mill";
    for (const char* name : {"X", "Y", "Z"}) {
        AxisConfig a;
        a.name = name;
        a.definitions = {name};
        a.maxVelocity = name[0] == 'Z' ? 20000 : 30000;
        a.maxAcceleration = name[0] == 'Z' ? 2000 : 2500;
        p.axes.push_back(a);
    }
    ToolConfig tool;
    tool.number = 5;
    tool.radius = 3.0;
    p.tools.push_back(tool);
    return p;
}

CompileResult compileLa(const std::string& source, LookAheadDefaults defaults = {}) {
    static const ProcessConfig process = millProcess();
    CompilerOptions options;
    options.compilerActive = true;
    options.process = &process;
    options.programNumber = 1;
    CompilerPassList passes = standardCompilerPasses();
    for (auto& pass : passes)
        if (pass->name() == "look-ahead") pass = std::make_shared<LookAheadPass>(defaults);
    return Compiler(passes).compile(source, options);
}

bool hasCode(const CompileResult& r, const std::string& code, const std::string& block = "") {
    return std::any_of(r.errors.begin(), r.errors.end(), [&](const CompilerError& e) {
        return e.code == code && (block.empty() || e.block == block);
    });
}

std::string errorList(const CompileResult& r) {
    std::string s;
    for (const CompilerError& e : r.errors)
        s += e.block + " " + e.code + " " + e.message + "\n";
    return s;
}

/// 200 blocks of 0.25 mm along a gentle wave, a corner, and a circle.
std::string shortBlockProgram() {
    std::string text = "N0001 G0 G17 G90 X0 Y0 Z0\nN0002 F9000 METB=4 VFBT=2\nN0003 LA_ON\n";
    int n = 4;
    char line[80];
    for (int i = 1; i <= 200; ++i) {
        std::snprintf(line, sizeof line, "N%04d G1 X%.3f Y%.3f\n", n++, i * 0.25,
                      0.5 * std::sin(i * 0.05));
        text += line;
    }
    text += "N0204 G1 X50 Y20\nN0205 G2 X50 Y20 I50 J25 F12000\nN0206 G1 X20 Y20\n";
    text += "N0207 LA_OFF\nN0208 G0 X0 Y0\n";
    return text;
}

}  // namespace

TEST(LookAheadPass, ObjectBlocksStayWithinEveryAxisLimit) {
    const CompileResult r = compileLa(shortBlockProgram());
    ASSERT_EQ(r.status, CompileStatus::Compiled) << errorList(r);
    const auto moves = objectMoves(r.objectText, millLimits());
    ASSERT_GT(moves.size(), 200u);
    const auto violations = objectViolations(moves, millLimits(), 4.0);
    EXPECT_TRUE(violations.empty()) << violations.size() << " first: " << violations.front();
    // The source's F holds again after LA_OFF.
    const auto lines = mtc::test::objectBlocks(r);
    EXPECT_NE(std::find(lines.begin(), lines.end(), "N0207:0000 G1 F12000"), lines.end());
}

TEST(LookAheadPass, DecelerationSplitsALongBlockIntoSubBlocks) {
    const CompileResult r =
        compileLa("N0001 G0 X0 Y0\nN0002 LA_ON\nN0003 G1 X400 F24000\nN0004 LA_OFF\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled) << errorList(r);
    const auto lines = mtc::test::objectBlocks(r);
    std::vector<std::string> parts;
    for (const std::string& l : lines)
        if (l.rfind("N0003:", 0) == 0) parts.push_back(l);
    ASSERT_GE(parts.size(), 5u);
    EXPECT_EQ(parts[1].substr(0, 11), "N0003:0001 ");
    EXPECT_NE(parts.back().find("X400 F"), std::string::npos);
    const auto moves = objectMoves(r.objectText, millLimits());
    // Rising then falling F, the top at the programmed 24000.
    double top = 0;
    for (const ObjectMove& m : moves)
        top = std::max(top, m.feed);
    EXPECT_DOUBLE_EQ(top, 24000.0);
    EXPECT_LT(moves.back().feed, moves[moves.size() - 2].feed);
    EXPECT_TRUE(objectViolations(moves, millLimits(), 5.0).empty());
}

TEST(LookAheadPass, AxisFeedAccEffAndSwiftFunctions) {
    const CompileResult r = compileLa(
        "N0001 G0 X0 Y0\nN0002 LA_ON\nN0003 G1 X100 Y100 FY=3000 ACC_EFF=50 SE 1:5 QQ12 MQ7\n"
        "N0004 LA_OFF\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled) << errorList(r);
    const auto moves = objectMoves(r.objectText, millLimits());
    for (const ObjectMove& m : moves)
        EXPECT_LE(m.feed / std::sqrt(2.0), 3000.0 + 1e-9);
    EXPECT_TRUE(objectViolations(moves, millLimits(), 5.0, 0.5).empty());
    const auto lines = mtc::test::objectBlocks(r);
    EXPECT_NE(lines[2].find("SE 1:5 QQ12 MQ7"), std::string::npos) << lines[2];
    EXPECT_EQ(r.objectText.find("FY="), std::string::npos);
    EXPECT_EQ(r.objectText.find("ACC_EFF"), std::string::npos);
}

TEST(LookAheadPass, RadiusCorrectionWritesApproachCornerAndRetract) {
    const CompileResult r = compileLa(
        "N0001 G0 X0 Y0 T5\nN0002 TRC=2 ADTRC=2\nN0003 LA_ON\nN0004 G1 X10 F3000\n"
        "N0005 Y10\nN0006 LA_OFF\n");
    ASSERT_EQ(r.status, CompileStatus::Compiled) << errorList(r);
    const auto lines = mtc::test::objectBlocks(r);
    auto has = [&](const std::string& prefix) {
        return std::any_of(lines.begin(), lines.end(),
                           [&](const std::string& l) { return l.rfind(prefix, 0) == 0; });
    };
    // Tools list radius 3 of T5, right of the contour: Y-3 on the first side,
    // X13 on the second, the corner arc G3 around X10 Y0.
    EXPECT_TRUE(has("N0004:0000 G1 X-2 Y-3 F"));  // lead-in to the approach start
    EXPECT_TRUE(has("N0004:0001 G1 X0 F"));       // approach line
    EXPECT_TRUE(has("N0004:0002 G1 X10 F"));
    EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [](const std::string& l) {
        return l.find("G3 X13 Y0 I10 J0") != std::string::npos;
    }));
    const auto moves = objectMoves(r.objectText, millLimits());
    EXPECT_EQ(moves.back().element.end, point({10, 10, 0}));  // back to the programmed end
    EXPECT_TRUE(objectViolations(moves, millLimits(), 5.0).empty());
}

TEST(LookAheadPass, ToolRadiusFromTlRadiusAndAcdComp) {
    LookAheadDefaults defaults;
    defaults.readNcVariable = [](int process, int number) -> std::optional<double> {
        if (process == 0 && number == 200) return 2.5;
        return std::nullopt;
    };
    const std::string program =
        "N0001 G0 X0 Y0 T7 E2\nN0002 TL_RADIUS[ ] = ACD_COMP[@200]-0,5\nN0003 TRC=1\n"
        "N0004 LA_ON\nN0005 G1 X10 F3000\nN0006 LA_OFF\n";
    const CompileResult r = compileLa(program, defaults);
    ASSERT_EQ(r.status, CompileStatus::Compiled) << errorList(r);
    // Radius 2.5 - 0.5 = 2, left of +X: the tool runs on Y2.
    EXPECT_NE(r.objectText.find("G1 Y2 F"), std::string::npos) << r.objectText;
    EXPECT_NE(r.objectText.find("G1 X10 F"), std::string::npos) << r.objectText;
    // Without a controller the variable reads 0: a warning, and radius 0 -> no radius.
    const CompileResult cold = compileLa(program);
    EXPECT_TRUE(hasCode(cold, "LA_ACD_NO_CONTROLLER", "N0002"));
}

TEST(LookAheadPass, VelocityProfileExport) {
    const auto profiles = velocityProfiles(shortBlockProgram(), [] {
        static const ProcessConfig process = millProcess();
        CompilerOptions o;
        o.process = &process;
        return o;
    }());
    ASSERT_EQ(profiles.size(), 1u);
    const VelocityProfile& p = profiles[0];
    EXPECT_EQ(p.onLine, 3);
    EXPECT_EQ(p.rows.front().block, "N0004:0000");
    EXPECT_NEAR(p.rows.back().sEnd, p.length, 1e-9);
    double t = 0;
    for (const ProfileRow& row : p.rows) {
        EXPECT_NEAR(row.tStart, t, 1e-9);
        EXPECT_LE(row.feed, row.vMax + 1e-9);
        EXPECT_GE(row.time, 0.004 - 1e-12);
        t += row.time;
    }
    EXPECT_NEAR(t, p.time, 1e-9);
    EXPECT_DOUBLE_EQ(p.curve.front().v, 0.0);
    EXPECT_DOUBLE_EQ(p.curve.back().v, 0.0);
    const std::string csv = formatProfileCsv(p);
    EXPECT_EQ(csv.substr(0, 16), "block;line;gener");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), static_cast<long>(p.rows.size() + 1));
}

struct ErrorCase {
    const char* program;
    const char* code;
    const char* block;
};

TEST(LookAheadPass, EveryErrorConditionIsReportedAtItsBlock) {
    const ErrorCase cases[] = {
        {"N0001 LA_ON\nN0002 G1 X5 F100\n", "LA_OFF_MISSING", "N0001"},
        {"N0001 LA_OFF\n", "LA_OFF_WITHOUT_ON", "N0001"},
        {"N0001 LA_ON\nN0002 LA_ON\nN0003 LA_OFF\n", "LA_NESTED", "N0002"},
        {"N0001 LA_ON G1 X5\nN0002 LA_OFF\n", "LA_KEYWORD_NOT_ALONE", "N0001"},
        {"N0001 LA_ON\nN0002 G1 X5 F100 M8\nN0003 LA_OFF\n", "LA_COMMAND_NOT_ALLOWED", "N0002"},
        {"N0001 LA_ON\nN0002 G1 X5 F100 Q12\nN0003 LA_OFF\n", "LA_COMMAND_NOT_ALLOWED", "N0002"},
        {"N0001 LA_ON\nN0002 G4 F100\nN0003 LA_OFF\n", "LA_COMMAND_NOT_ALLOWED", "N0002"},
        {"N0001 LA_ON\nN0002 @1=2\nN0003 LA_OFF\n", "LA_COMMAND_NOT_ALLOWED", "N0002"},
        {"N0001 LA_ON\nN0002 BRA .X\nN0003 .X LA_OFF\n", "LA_COMMAND_NOT_ALLOWED", "N0002"},
        {"N0001 LA_ON\nN0002 METB=5\nN0003 LA_OFF\n", "LA_COMMAND_NOT_ALLOWED", "N0002"},
        {"N0001 G0 X0\nN0002 LA_ON\nN0003 X5\nN0004 LA_OFF\n", "LA_COMMAND_NOT_ALLOWED", "N0003"},
        {"N0001 LA_ON\nN0002 T5\nN0003 LA_OFF\n", "LA_TOOL_CHANGE", "N0002"},
        {"N0001 LA_ON\nN0002 G1 X@1 F100\nN0003 LA_OFF\n", "LA_VARIABLE_ENDPOINT", "N0002"},
        {"N0001 LA_ON\nN0002 G2 X2 Y0 I@1 F100\nN0003 LA_OFF\n", "LA_VARIABLE_ENDPOINT", "N0002"},
        {"N0001 LA_ON\nN0002 G1 X2 F@3\nN0003 LA_OFF\n", "LA_VARIABLE_FEED", "N0002"},
        {"N0001 LA_ON\nN0002 G1 X2\nN0003 LA_OFF\n", "LA_NO_FEED", "N0002"},
        {"N0001 LA_ON\nN0002 G2 X2 Y0 F100\nN0003 LA_OFF\n", "LA_ARC_CENTER", "N0002"},
        {"N0001 LA_ON\nN0002 G2 X2 Y0 K1 F100\nN0003 LA_OFF\n", "LA_ARC_CENTER", "N0002"},
        {"N0001 LA_ON\nN0002 G2 X2 Y0 I5 J0 F100\nN0003 LA_OFF\n", "LA_ARC_RADIUS", "N0002"},
        {"N0001 G91\nN0002 LA_ON\nN0003 LA_OFF\n", "LA_INCREMENTAL", "N0002"},
        {"N0001 G1 X@5\nN0002 LA_ON\nN0003 G1 X2 F100\nN0004 LA_OFF\n", "LA_START_UNKNOWN",
         "N0003"},
        {"N0001 LA_ON\n/N0002 G1 X2 F100\nN0003 LA_OFF\n", "LA_SKIP_BLOCK", "N0002"},
        {"N0001 G1 X1 FX=100\n", "LA_AXIS_FEED_OUTSIDE", "N0001"},
        {"N0001 LA_ON\nN0002 G1 X2 FA=100\nN0003 LA_OFF\n", "LA_UNKNOWN_AXIS", "N0002"},
        {"N0001 LA_ON\nN0002 G1 A2 F100\nN0003 LA_OFF\n", "LA_UNKNOWN_AXIS", "N0002"},
        {"N0001 METB=2\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 METB=31\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 VFBT=0.5\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 BBTRC=11\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 BBTRC=2.5\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 TRC=3\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 ADTRC=-1\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 ACC_EFF=201\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 TL_RADIUS[0,1]=2\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 TL_RADIUS[1,10]=2\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 TL_RADIUS[1,1]=1000\n", "LA_VALUE_RANGE", "N0001"},
        {"N0001 TL_RADIUS=2\n", "LA_TL_RADIUS_SYNTAX", "N0001"},
        {"N0001 METB\n", "LA_VALUE_MISSING", "N0001"},
        {"N0001 VFBT=2/0\n", "LA_BAD_VALUE", "N0001"},
        {"N0001 ACD_COMP[@5]\n", "LA_ACD_ALONE", "N0001"},
        {"N0001 TRC=1\nN0002 LA_ON\nN0003 LA_OFF\n", "LA_TRC_NO_RADIUS", "N0002"},
        {"N0001 T5 TRC=1\nN0002 LA_ON\nN0003 G3 X4 Y0 I2 J0 F100\nN0004 LA_OFF\n",
         "LA_TRC_RADIUS_TOO_LARGE", "N0003"},
        {"N0001 T5 TRC=1\nN0002 LA_ON\nN0003 G1 X10 F100\nN0004 Y1\nN0005 X0\nN0006 LA_OFF\n",
         "LA_TRC_ELEMENT_TOO_SHORT", "N0004"},
        {"N0001 T5 TRC=1\nN0002 LA_ON\nN0003 G1 Z-5 F100\nN0004 LA_OFF\n", "LA_TRC_NO_PLANE_MOTION",
         "N0003"},
        {"N0001 T5 TRC=1\nN0002 LA_ON\nN0003 G1 X10 F100\nN0004 X5\nN0005 LA_OFF\n",
         "LA_TRC_REVERSAL", "N0004"},
    };
    for (const ErrorCase& c : cases) {
        const CompileResult r = compileLa(c.program);
        EXPECT_TRUE(hasCode(r, c.code, c.block))
            << c.program << "expected " << c.code << " at " << c.block << ", got:\n"
            << errorList(r);
        EXPECT_EQ(r.status, CompileStatus::Error) << c.program;
    }
}

TEST(LookAheadPass, MetbMustExceedTheBlockCycleTime) {
    LookAheadDefaults defaults;
    defaults.blockCycleMs = 4.0;
    const CompileResult r = compileLa("N0001 METB=3\nN0002 LA_ON\nN0003 LA_OFF\n", defaults);
    EXPECT_TRUE(hasCode(r, "LA_METB_CYCLE", "N0002")) << errorList(r);
}

TEST(LookAheadPass, ProcessParametersOverrideThePresets) {
    ProcessConfig process = millProcess();
    process.parameters["B070"] = "9";  // METB 9 ms instead of the preset 5
    CompilerOptions options;
    options.compilerActive = true;
    options.process = &process;
    const std::string program =
        "N0001 G0 X0 Y0\nN0002 LA_ON\nN0003 G1 X0.5 F30000\nN0004 X1\n"
        "N0005 X1.5\nN0006 LA_OFF\n";
    const CompileResult r = Compiler().compile(program, options);
    ASSERT_EQ(r.status, CompileStatus::Compiled) << errorList(r);
    const auto moves = objectMoves(r.objectText, millLimits());
    EXPECT_TRUE(objectViolations(moves, millLimits(), 9.0).empty());
    // 0.5 mm in at least 9 ms: F <= 3333.3 mm/min.
    for (const ObjectMove& m : moves)
        EXPECT_LE(m.feed, 0.5 / 0.009 * 60.0);
    process.parameters["B073"] = "10";  // block cycle time above METB
    EXPECT_TRUE(hasCode(Compiler().compile(program, options), "LA_METB_CYCLE", "N0002"));
}

TEST(LookAheadPass, RandomTextsNeverCrashAndAlwaysEnd) {
    const char* pieces[] = {"LA_ON",
                            "LA_OFF",
                            "G1",
                            "G2",
                            "G3",
                            "X1.5",
                            "Y-2",
                            "I0",
                            "J3",
                            "F500",
                            "FX=200",
                            "TRC=1",
                            "TRC=2",
                            "T5",
                            "ADTRC=1",
                            "METB=4",
                            "ACC_EFF=80",
                            "TL_RADIUS[5,1]=1",
                            "ACD_COMP[@3]",
                            "SE 1:2",
                            "@1=2",
                            "X@1",
                            "G91",
                            "G90",
                            "/",
                            "\n",
                            "\n",
                            "\n",
                            "Z1",
                            "G18"};
    std::mt19937 random(61);
    std::uniform_int_distribution<size_t> pick(0, sizeof pieces / sizeof pieces[0] - 1);
    for (int round = 0; round < 300; ++round) {
        std::string text;
        for (int k = 0; k < 60; ++k)
            text += std::string(pieces[pick(random)]) + " ";
        const CompileResult r = compileLa(text);
        if (r.status == CompileStatus::Compiled) {
            const auto moves = objectMoves(r.objectText, millLimits());
            for (const ObjectMove& m : moves)
                EXPECT_GT(m.feed, 0.0);
        } else {
            EXPECT_FALSE(r.errors.empty());
        }
    }
}
