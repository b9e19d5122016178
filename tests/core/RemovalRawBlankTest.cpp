// A GNE RAW contour after the lathe's drawing window is the blank the
// material removal cuts (issue 19 §3, TP-021): a pre-turned preform is not
// cut in the air, its volume is the stock's, and a RAW contour that does not
// solve is diagnosed at its line instead of being replaced by the whole bar.
#include <gtest/gtest.h>

#include <cmath>

#include "InterpTestSupport.h"
#include "cnc_core/removal/ProgramStock.h"
#include "cnc_core/removal/RemovalRun.h"

namespace {

using namespace mtc::core;
using namespace mtc::core::removal;
using namespace mtc::test;

constexpr double kPi = 3.14159265358979323846;
constexpr int kLathe = 1;

ProgramStore storeWith(const std::string& source) {
    ProgramStore store;
    store.put(kLathe, 1, parse(source, 1));
    return store;
}

RemovalRunResult simulate(const std::string& source) {
    RemovalSettings settings;
    settings.resolution = 0.2;
    return simulateRemoval(demoCell().processes[kLathe], storeWith(source), 1, settings);
}

ProgramStock stockOf(const std::string& source) {
    return programStock(demoCell().processes[kLathe], storeWith(source), 1);
}

/// A bar of radius 30 from Z-60 to Z2 (window) whose preform is turned to
/// radius 20 from Z-30 on (RAW contour 4, lines 3..8); a pass at radius 18
/// from Z5 to Z-20 follows. `prefix` is "" (GNE form) or ";" (as the
/// compiler leaves the GNE lines).
std::string steppedPreform(const std::string& prefix) {
    return "N0001 G18 G54 G90 G0 X50 Z5\n" + prefix + "WINDOW_01 (-60, 2, 30)\n" + prefix +
           "CONT (4, RAW)\n" + prefix + "START Z2 X20\n" + prefix + "LINE Z-30 X20\n" + prefix +
           "LINE Z-30 X30\n" + prefix + "LINE Z-60 X30\n" + prefix +
           "END_CONT\n"
           "N0010 G0 X18 Z5\nN0011 G1 Z-20 F0.2\nN0012 G0 X50\nN0013 M30\n";
}

TEST(RemovalRawBlank, TheRawContourAfterTheWindowIsTheBlank) {
    for (const std::string prefix : {"", ";"}) {
        const std::string program = steppedPreform(prefix);
        const ProgramStock stock = stockOf(program);
        ASSERT_FALSE(stock.diagnostics.hasErrors()) << diagnosticsText(stock.diagnostics);
        EXPECT_EQ(stock.origin.rawContour, 4) << prefix;
        EXPECT_EQ(stock.origin.rawLine, 3u);
        ASSERT_EQ(stock.stock.shape, Stock::Shape::Cylinder);
        EXPECT_EQ(stock.stock.radius, 30.0);
        ASSERT_FALSE(stock.stock.outline.empty());

        const RemovalRunResult r = simulate(program);
        ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
        const TurnedProfile& profile = *r.part->profile();
        // Demo lathe G54: Z255.5. The blank: radius 30 up to Z-30, 20 beyond.
        EXPECT_NEAR(profile.blankVolume(), kPi * (30.0 * 30.0 * 30.0 + 20.0 * 20.0 * 32.0), 1e-6);
        // Only the preform's material is cut: from radius 20 to 18 over
        // Z-20..2 (the slices' centres lie 0.1 mm inside every edge).
        EXPECT_NEAR(r.part->removedVolume(), kPi * (20.0 * 20.0 - 18.0 * 18.0) * 22.0, 1e-6);
        const auto sliceAt = [&](double z) {
            return static_cast<int>(std::floor((z + 255.5 - profile.from()) / 0.2));
        };
        EXPECT_NEAR(profile.radiusAt(sliceAt(-45.0)), 30.0, 1e-9);
        EXPECT_NEAR(profile.radiusAt(sliceAt(-25.0)), 20.0, 1e-9);
        EXPECT_NEAR(profile.radiusAt(sliceAt(-10.0)), 18.0, 1e-9);
    }
}

TEST(RemovalRawBlank, WithoutARawContourTheWholeBarIsTheBlank) {
    // The same pass on the bar: radius 30 to 18 over Z-20..2.
    const std::string program =
        "N0001 G18 G54 G90 G0 X50 Z5\n;WINDOW_01 (-60, 2, 30)\n"
        "N0010 G0 X18 Z5\nN0011 G1 Z-20 F0.2\nN0012 G0 X50\nN0013 M30\n";
    const ProgramStock stock = stockOf(program);
    EXPECT_EQ(stock.origin.rawContour, 0);
    EXPECT_TRUE(stock.stock.outline.empty());
    const RemovalRunResult r = simulate(program);
    ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
    EXPECT_NEAR(r.part->profile()->blankVolume(), kPi * 30.0 * 30.0 * 62.0, 1e-6);
    EXPECT_NEAR(r.part->removedVolume(), kPi * (30.0 * 30.0 - 18.0 * 18.0) * 22.0, 1e-6);
}

TEST(RemovalRawBlank, OnlyTheFirstRawContourBeforeTheNextWindowCounts) {
    // A final contour is not the blank (not even with "raw" in its comment);
    // a RAW contour after a second window belongs to that window.
    const std::string program =
        "N0001 G18 G54 G0 X50 Z5\nWINDOW_01 (-60, 2, 30)\nCONT (1, FINAL) ;drawn part\n"
        "START Z0 X0\n"
        "LINE Z0 X10\nLINE Z-20 X10\nEND_CONT\n"
        "WINDOW_01 (-60, 2, 30)\nCONT (3, RAW)\nSTART Z2 X20\nLINE Z-60 X20\nEND_CONT\n"
        "N0020 M30\n";
    const ProgramStock stock = stockOf(program);
    EXPECT_EQ(stock.origin.rawContour, 0) << diagnosticsText(stock.diagnostics);
    EXPECT_TRUE(stock.stock.outline.empty());

    const std::string twoRaw =
        "N0001 G18 G54 G0 X50 Z5\nWINDOW_01 (-60, 2, 30)\nCONT (5, RAW)\nSTART Z2 X20\n"
        "LINE Z-30 X20\nEND_CONT\nCONT (6, RAW)\nSTART Z2 X10\nLINE Z-60 X10\nEND_CONT\n"
        "N0020 M30\n";
    const ProgramStock first = stockOf(twoRaw);
    EXPECT_EQ(first.origin.rawContour, 5);
    EXPECT_EQ(first.origin.rawLine, 3u);
}

TEST(RemovalRawBlank, ARawContourThatDoesNotSolveIsAnErrorAtItsLine) {
    const std::string program =
        "N0001 G18 G54 G0 X50 Z5\n;WINDOW_01 (-60, 2, 30)\nN0003 ;CONT (7, RAW)\n"
        ";START Z2 X20\n;LINE A180\n;LINE A200\n;END_CONT\nN0010 G1 X18 Z-10 F0.2\nN0011 M30\n";
    const ProgramStock stock = stockOf(program);
    ASSERT_TRUE(stock.diagnostics.hasErrors());
    const Diagnostic& error = stock.diagnostics.items().front();
    EXPECT_EQ(error.code, "REMOVAL_RAW_CONTOUR");
    EXPECT_EQ(error.where.line, 3);
    EXPECT_EQ(error.where.block, "N0003");
    EXPECT_NE(error.message.find("RAW contour 7"), std::string::npos) << error.message;
    EXPECT_EQ(stock.stock.shape, Stock::Shape::None);
    const RemovalRunResult r = simulate(program);
    EXPECT_FALSE(r.part);
    EXPECT_TRUE(r.diagnostics.hasErrors());
}

TEST(RemovalRawBlank, AnOutlineThatWindsOverTheBarTooOftenIsRefusedUnchanged) {
    TurnedProfile profile(30.0, 0.0, 100.0, 1000);
    std::vector<std::array<double, 2>> outline;
    for (int i = 0; i < 20'002; ++i)  // every edge spans all 1,000 slices
        outline.push_back({i % 2 == 0 ? -1.0 : 101.0, i % 4 < 2 ? 16.0 : 12.0});
    EXPECT_FALSE(profile.shapeBlank(outline));
    EXPECT_EQ(profile.radiusAt(500), 30.0);
    EXPECT_NEAR(profile.blankVolume(), kPi * 30.0 * 30.0 * 100.0, 1e-6);
    outline.resize(19'000);  // 19,000,000 visits: within the bound
    EXPECT_TRUE(profile.shapeBlank(outline));
    EXPECT_EQ(profile.radiusAt(500), 16.0);
    EXPECT_EQ(profile.removedVolume(), 0.0);
}

}  // namespace
