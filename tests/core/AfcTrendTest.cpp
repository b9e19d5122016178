// The adaptive feed trend keeps a move without G26 as one record and makes
// its samples when read (AfcObservedMove); arcs are placed in the raw part by
// their box when it decides all their points (AfcMaterial).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "InterpTestSupport.h"
#include "cnc_core/afc/AfcMaterial.h"
#include "cnc_core/afc/AfcObservedMove.h"
#include "cnc_core/afc/AfcTrendRecorder.h"
#include "cnc_core/toolpath/Stock.h"

namespace {

using namespace mtc::core;

AfcObservedMove observedMove(double start, int count) {
    AfcObservedMove move;
    move.constant.limitingTorque = 50.0;
    move.constant.effectiveFeed = 1200.0;
    move.startTime = start;
    move.plannedSeconds = 0.01 * count;
    move.count = count;
    move.feed = 1200.0;
    move.speedFraction = 0.1;
    move.engagement = 0.8;
    move.cutFrom = 0.25;
    move.cutTo = 0.75;
    move.itmMeasured = true;
    move.itmFrom = 0.005;
    move.itmTo = 0.015;
    move.idleTorque = 7.5;
    move.stallCompensation = 1.25;
    return move;
}

TEST(AfcTrend, AnObservedMoveGivesTheTorqueOfEachMomentOfIt) {
    const AfcObservedMove move = observedMove(3.0, 8);
    for (int k = 1; k <= move.count; ++k) {
        const AfcTrendSample s = move.sample(k);
        const double elapsed = k * 0.01;
        EXPECT_NEAR(s.time, 3.0 + elapsed, 1e-12);
        const double share = elapsed / move.plannedSeconds;
        const double engagement = share >= 0.25 && share < 0.75 ? 0.8 : 0.0;
        const double actual = move.model.actualTorque(1200.0, 0.1, engagement, s.time);
        EXPECT_NEAR(s.torqueActual, actual, 1e-9) << "sample " << k;
        EXPECT_NEAR(s.machiningTorque, actual - 7.5 - 1.25, 1e-9);
        EXPECT_EQ(s.measuringIdle, k == 1) << "sample " << k;  // 10 ms lies in 5..15 ms
        EXPECT_EQ(s.limitingTorque, 50.0);
        EXPECT_EQ(s.effectiveFeed, 1200.0);
    }
    // In the cut the torque is the engagement's, outside it the friction's.
    EXPECT_GT(move.sample(4).torqueActual, move.sample(1).torqueActual + 20.0);
    EXPECT_LT(move.sample(8).torqueActual, move.sample(4).torqueActual - 20.0);
}

TEST(AfcTrend, TheOldestSamplesGoFirstAcrossRecords) {
    AfcTrendRecorder recorder(7);
    AfcTrendSample single;
    single.time = 1.0;
    recorder.add(single);
    recorder.add(observedMove(2.0, 5));  // 2.01 .. 2.05
    recorder.add(observedMove(4.0, 4));  // 4.01 .. 4.04
    ASSERT_EQ(recorder.size(), 7u);
    // The single sample and the first two of the first move are gone.
    EXPECT_NEAR(recorder.at(0).time, 2.03, 1e-12);
    EXPECT_NEAR(recorder.at(2).time, 2.05, 1e-12);
    EXPECT_NEAR(recorder.at(3).time, 4.01, 1e-12);
    EXPECT_NEAR(recorder.at(6).time, 4.04, 1e-12);
    EXPECT_NEAR(recorder.at(99).time, 4.04, 1e-12);  // past the end: the newest
    const std::vector<AfcTrendSample> all = recorder.samples();
    ASSERT_EQ(all.size(), 7u);
    for (std::size_t i = 0; i < all.size(); ++i) {
        EXPECT_EQ(all[i].time, recorder.at(i).time) << i;
        EXPECT_EQ(all[i].torqueActual, recorder.at(i).torqueActual) << i;
    }
    const std::string csv = recorder.csv();
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 8);
    EXPECT_NE(csv.find("\n2.0300,"), std::string::npos);
    recorder.add(observedMove(9.0, 20));  // more than the capacity at once
    EXPECT_EQ(recorder.size(), 7u);
    EXPECT_NEAR(recorder.at(0).time, 9.14, 1e-12);
    recorder.clear();
    EXPECT_EQ(recorder.size(), 0u);
    EXPECT_EQ(recorder.at(0).time, 0.0);  // empty: a default sample, no crash
}

/// An arc in the XY plane of the demo mill around (cx, cy) at height z,
/// from angle 0 counter-clockwise to angle `turn` (radians).
Motion arc(double cx, double cy, double radius, double z, double turn) {
    Motion m;
    m.type = MotionType::ArcCCW;
    m.axisCount = 3;
    m.start = {cx + radius, cy, z};
    m.end = {cx + radius * std::cos(turn), cy + radius * std::sin(turn), z};
    m.planeAxis1 = 0;
    m.planeAxis2 = 1;
    m.center1 = cx;
    m.center2 = cy;
    return m;
}

TEST(AfcMaterialArcs, ArcsOutsideInsideAndAcrossTheBlock) {
    const ProcessConfig process = *mtc::test::demoCell().process(0);
    const Stock stock = stockOf(process);
    ASSERT_EQ(stock.shape, Stock::Shape::Block);
    const AfcMaterial material(process);
    const double cx = (stock.min[0] + stock.max[0]) / 2, cy = (stock.min[1] + stock.max[1]) / 2;
    const double z = (stock.min[2] + stock.max[2]) / 2;
    const double small = std::min(stock.max[0] - cx, stock.max[1] - cy) / 2;
    const MaterialShare inside = material.along(arc(cx, cy, small, z, 3.0));
    EXPECT_EQ(inside.from, 0.0);
    EXPECT_EQ(inside.to, 1.0);
    const MaterialShare above = material.along(arc(cx, cy, small, stock.max[2] + 1.0, 3.0));
    EXPECT_GT(above.from, above.to) << "nothing inside";
    // A quarter turn from inside across the stock's Y side (the block is
    // wider in X than in Y): it cuts from its start to part of the way.
    const double hx = stock.max[0] - cx, hy = stock.max[1] - cy;
    ASSERT_GT(hx, hy);
    const MaterialShare across = material.along(arc(cx, cy, (hx + hy) / 2, z, M_PI / 2));
    EXPECT_EQ(across.from, 0.0);
    EXPECT_GT(across.to, 0.0);
    EXPECT_LT(across.to, 1.0);
}

TEST(StockBox, BlockCylinderAndNone) {
    std::array<double, 3> low{}, high{};
    Stock none;
    EXPECT_FALSE(none.box(low, high));
    Stock block;
    std::string error;
    ASSERT_TRUE(parseStock("block -10 10 -5 5 -3 0", block, error)) << error;
    ASSERT_TRUE(block.box(low, high));
    EXPECT_EQ(low, (std::array<double, 3>{-10, -5, -3}));
    EXPECT_EQ(high, (std::array<double, 3>{10, 5, 0}));
    Stock bar;
    ASSERT_TRUE(parseStock("cylinder Z 40 0 120", bar, error)) << error;
    ASSERT_TRUE(bar.box(low, high));
    EXPECT_EQ(low, (std::array<double, 3>{-40, -40, 0}));
    EXPECT_EQ(high, (std::array<double, 3>{40, 40, 120}));
}

}  // namespace
