// The look-ahead's split of a segment into sub-blocks does not grow with a
// programmed feed or length (issue 15 §1, LA-006: at most 8 pieces per
// acceleration or deceleration phase), whatever the numbers.
#include <gtest/gtest.h>

#include "CompilerTestSupport.h"

using namespace mtc::core;
using namespace mtc::test;

namespace {

TEST(LookAheadLimits, HugeFeedsAndLengthsGiveABoundedSplit) {
    for (const char* feed : {"F99999999999999", "F1", "F0.000000000001"}) {
        for (const char* length : {"X999", "X99999999999999", "X0.001"}) {
            const std::string source =
                std::string("N0001 G0 G17 G90 X0 Y0\nN0002 METB=30 ACC_EFF=1\n") +
                "N0003 LA_ON\nN0004 G1 " + length + " " + feed +
                "\nN0005 Y999\nN0006 LA_OFF\nN0007 M30\n";
            const CompileResult r = compileText(source);
            // two moves, each at most 2 phases of 8 pieces, plus the blocks around
            EXPECT_LE(objectBlocks(r).size(), 7u + 2u * 2u * 8u) << source;
        }
    }
}

}  // namespace
