// The positions of the panel's override switches (MOT-016).
#include <gtest/gtest.h>

#include <vector>

#include "cnc_core/machine/OverrideSwitch.h"

namespace {

using mtc::core::feedOverrideStep;
using mtc::core::rapidOverrideStep;

TEST(OverrideSwitch, FeedStepsAreFineBelowTenPercentAndTensAbove) {
    int percent = 0;
    std::vector<int> up;
    for (int i = 0; i < 25; ++i)
        up.push_back(percent = feedOverrideStep(percent, 1, 150));
    const std::vector<int> expected = {1,   2,   4,   6,   8,   10,  20,  30,  40,
                                       50,  60,  70,  80,  90,  100, 110, 120, 130,
                                       140, 150, 150, 150, 150, 150, 150};
    EXPECT_EQ(up, expected);
    EXPECT_EQ(feedOverrideStep(150, -1, 150), 140);
    EXPECT_EQ(feedOverrideStep(0, -1, 150), 0) << "the lower end stays";
}

TEST(OverrideSwitch, AValueBetweenPositionsGoesToTheNextInThatDirection) {
    EXPECT_EQ(feedOverrideStep(55, 1, 150), 60);
    EXPECT_EQ(feedOverrideStep(55, -1, 150), 50);
    EXPECT_EQ(feedOverrideStep(3, -1, 150), 2);
    EXPECT_EQ(feedOverrideStep(120, 1, 125), 125) << "a maximum off the tens is a position";
    EXPECT_EQ(feedOverrideStep(125, -1, 125), 120);
    EXPECT_EQ(feedOverrideStep(100, 1, 100), 100);
}

TEST(OverrideSwitch, RapidPositions) {
    EXPECT_EQ(rapidOverrideStep(100, -1), 50);
    EXPECT_EQ(rapidOverrideStep(50, -1), 25);
    EXPECT_EQ(rapidOverrideStep(25, -1), 10);
    EXPECT_EQ(rapidOverrideStep(10, -1), 1);
    EXPECT_EQ(rapidOverrideStep(1, -1), 0);
    EXPECT_EQ(rapidOverrideStep(0, -1), 0);
    EXPECT_EQ(rapidOverrideStep(30, 1), 50);
    EXPECT_EQ(rapidOverrideStep(100, 1), 100);
}

}  // namespace
