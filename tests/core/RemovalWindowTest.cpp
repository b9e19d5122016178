// The GNE drawing window as the stock of the material removal (issue 19 §3,
// TP-008): WINDOW_02 / WINDOW_01 in workpiece coordinates, converted with
// the zero offset in force at the window; bad windows are diagnosed at their
// block and line, and a huge one stays within the part model's cell bound.
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

ProgramStore storeWith(const std::string& source, int process) {
    ProgramStore store;
    store.put(process, 1, parse(source, 1));
    return store;
}

RemovalRunResult simulate(const std::string& source, int process) {
    RemovalSettings settings;
    settings.resolution = 0.2;
    return simulateRemoval(demoCell().processes[static_cast<std::size_t>(process)],
                           storeWith(source, process), 1, settings);
}

/// A 40 x 20 pocket 4 deep (X20..60, Y20..40) milled by the centre of T1
/// (radius 3.5) under `offset`, after `window` (a compiled GNE window line).
std::string pocket(const std::string& offset, const std::string& window) {
    return "N0001 T1 G17 G90 " + offset + " G0 X40 Y30 Z2\n" + window +
           "N0003 S2000 M3\nN0004 G1 Z-4 F200\nN0005 X56.5\nN0006 Y30\nN0007 X23.5\n"
           "N0008 Y36.5\nN0009 X56.5\nN0010 Y23.5\nN0011 X23.5\nN0012 Y36.5\nN0013 G0 Z2\n"
           "N0014 M30\n";
}

double pocketVolume() {
    return (40.0 * 20.0 - (4.0 - kPi) * 3.5 * 3.5) * 4.0;
}

TEST(RemovalWindow, Window02UnderG55IsTheStockInMachineCoordinates) {
    // Demo mill: G55 = X50 Y-80 Z-120; the configuration's block lies at
    // X-150..-50, far from a part machined under G55.
    const std::string program = pocket("G55", "N0002 ;WINDOW_02 (10, 10, 70, 50, 0, -8)\n");
    const ProgramStock stock = programStock(demoCell().processes[0], storeWith(program, 0), 1);
    ASSERT_FALSE(stock.diagnostics.hasErrors()) << diagnosticsText(stock.diagnostics);
    EXPECT_TRUE(stock.origin.fromWindow);
    EXPECT_EQ(stock.origin.keyword, "WINDOW_02");
    EXPECT_EQ(stock.origin.zeroOffset, 55);
    EXPECT_EQ(stock.origin.where.program, 1);
    EXPECT_EQ(stock.origin.where.line, 2);
    EXPECT_EQ(stock.origin.where.block, "N0002");
    ASSERT_EQ(stock.stock.shape, Stock::Shape::Block);
    EXPECT_EQ(stock.stock.min, (std::array<double, 3>{60, -70, -128}));
    EXPECT_EQ(stock.stock.max, (std::array<double, 3>{120, -30, -120}));

    const RemovalRunResult r = simulate(program, 0);
    ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
    EXPECT_FALSE(r.diagnostics.hasErrors()) << diagnosticsText(r.diagnostics);
    EXPECT_TRUE(r.stock.fromWindow);
    const Box& box = r.part->heightField()->stock();
    EXPECT_EQ(box.min, stock.stock.min);
    EXPECT_EQ(box.max, stock.stock.max);
    // The pocket inside the window, within the border cells (D-020).
    EXPECT_NEAR(r.part->removedVolume(), pocketVolume(), 120 * std::sqrt(2.0) * 0.2 * 4.0);
    EXPECT_EQ(r.counts.rapidCuts, 0u);

    // Without the window the configuration's block is the stock: nothing cut.
    const RemovalRunResult plain = simulate(pocket("G55", "N0002 M8\n"), 0);
    ASSERT_TRUE(plain.part);
    EXPECT_FALSE(plain.stock.fromWindow);
    EXPECT_EQ(plain.part->removedVolume(), 0.0);
}

TEST(RemovalWindow, TheGneFormAndTheZeroOffsetAtTheWindowNotAtTheStart) {
    // G54 at the start, G55 before the window: the window is in G55. The
    // GNE form of the line (not compiled) is read the same way.
    const std::string program =
        "N0001 G54 G0 X0 Y0 Z50\nN0002 G55\nN0003 WINDOW_02 (0, 0, 20, 10)\n"
        "N0004 M30\n";
    const ProgramStock stock = programStock(demoCell().processes[0], storeWith(program, 0), 1);
    ASSERT_FALSE(stock.diagnostics.hasErrors()) << diagnosticsText(stock.diagnostics);
    EXPECT_EQ(stock.origin.zeroOffset, 55);
    EXPECT_EQ(stock.origin.where.block, "N0003");
    EXPECT_EQ(stock.stock.min, (std::array<double, 3>{50, -80, -130}));  // ZBOT -10
    EXPECT_EQ(stock.stock.max, (std::array<double, 3>{70, -70, -120}));  // ZTOP 0
}

TEST(RemovalWindow, Window01IsTheLathesBarAlongZ) {
    // Demo lathe: G54 = X0 Z255.5.
    const std::string program =
        "N0001 G18 G54 G90 G0 X100 Z20\nN0002 ;WINDOW_01 (-45, 1, 40)\n"
        "N0003 G1 X70 F0.2\nN0004 Z-20\nN0005 G0 X100\nN0006 M30\n";
    const ProgramStock stock = programStock(demoCell().processes[1], storeWith(program, 1), 1);
    ASSERT_FALSE(stock.diagnostics.hasErrors()) << diagnosticsText(stock.diagnostics);
    ASSERT_EQ(stock.stock.shape, Stock::Shape::Cylinder);
    EXPECT_EQ(stock.stock.axis, 2);
    EXPECT_EQ(stock.stock.radius, 40.0);
    EXPECT_EQ(stock.stock.from, 210.5);
    EXPECT_EQ(stock.stock.to, 256.5);
    const RemovalRunResult r = simulate(program, 1);
    ASSERT_TRUE(r.part) << diagnosticsText(r.diagnostics);
    EXPECT_EQ(r.part->profile()->stockRadius(), 40.0);
    EXPECT_EQ(r.part->profile()->from(), 210.5);
    EXPECT_EQ(r.part->profile()->to(), 256.5);
    // A bore is not simulated: a warning, the bar stays solid.
    const std::string bored =
        "N0001 G18 G54 G0 X100 Z20\nN0002 ;WINDOW_01 (-45, 1, 40, 10)\n"
        "N0003 M30\n";
    const ProgramStock withBore = programStock(demoCell().processes[1], storeWith(bored, 1), 1);
    EXPECT_FALSE(withBore.diagnostics.hasErrors());
    ASSERT_EQ(withBore.diagnostics.items().size(), 1u);
    EXPECT_EQ(withBore.diagnostics.items().front().code, "REMOVAL_WINDOW_SIMPLIFIED");
    EXPECT_EQ(withBore.stock.shape, Stock::Shape::Cylinder);
}

TEST(RemovalWindow, BadWindowsAreDiagnosedAtTheirBlockAndCutNothing) {
    struct Case {
        const char* window;
        const char* says;
    };
    for (const Case& c :
         {Case{"WINDOW_02 (10, 10, 10, 50)", "XMIN and XMAX are equal"},
          Case{"WINDOW_02 (10, 10, 70, 10)", "YMIN and YMAX are equal"},
          Case{"WINDOW_02 (10, 10, 70, 50, -8, 0)", "ZTOP must lie above ZBOT"},
          Case{"WINDOW_02 (10, 10, 1e9, 50)", "is not a number"},
          Case{"WINDOW_02 (10, 10, 5000000, 50)", "is outside"},
          Case{"WINDOW_02 (10, nan, 70, 50)", "is not a number"},
          Case{"WINDOW_02 (10, 10)", "WINDOW_02"}, Case{"WINDOW_03 (1, 2)", "WINDOW_03"}}) {
        SCOPED_TRACE(c.window);
        const RemovalRunResult r =
            simulate(pocket("G54", std::string("N0002 ;") + c.window + "\n"), 0);
        EXPECT_FALSE(r.part);
        ASSERT_TRUE(r.diagnostics.hasErrors());
        const Diagnostic& d = r.diagnostics.items().front();
        EXPECT_EQ(d.code, "REMOVAL_WINDOW") << diagnosticsText(r.diagnostics);
        EXPECT_EQ(d.where.program, 1);
        EXPECT_EQ(d.where.block, "N0002");
        EXPECT_EQ(d.where.line, 2);
        EXPECT_NE(d.message.find(c.says), std::string::npos) << d.message;
    }
}

TEST(RemovalWindow, AHugeWindowStaysWithinTheCellBound) {
    // 1,000,000 mm square (the GNE's largest value): refused by the cell
    // bound with the coarsest resolution that fits, at the window's block.
    const RemovalRunResult r =
        simulate(pocket("G54", "N0002 ;WINDOW_02 (-1000000, -1000000, 1000000, 1000000)\n"), 0);
    EXPECT_FALSE(r.part);
    ASSERT_TRUE(r.diagnostics.hasErrors());
    const Diagnostic& d = r.diagnostics.items().back();
    EXPECT_EQ(d.code, "REMOVAL_STOCK") << diagnosticsText(r.diagnostics);
    EXPECT_EQ(d.where.block, "N0002");
    EXPECT_NE(d.message.find("WINDOW_02"), std::string::npos) << d.message;
}

}  // namespace
