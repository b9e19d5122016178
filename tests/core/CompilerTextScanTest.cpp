// The caseless keyword pre-check that lets passes skip programs without
// their keywords (issue 6 speed target).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "cnc_core/compiler/Compiler.h"
#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/NameScan.h"

namespace mtc::core {
namespace {

TEST(CompilerTextScan, FindsNeedlesWithoutCase) {
    EXPECT_TRUE(containsAnyCaseless("X10 la_on", {"LA_"}));
    EXPECT_TRUE(containsAnyCaseless("CONT (1)", {"START", "CONT"}));
    EXPECT_TRUE(containsAnyCaseless("g1 ccw", {"CW"}));
    EXPECT_FALSE(containsAnyCaseless("X10 Y20 F1200 M8", {"CONT", "LA_", "TRC"}));
    EXPECT_FALSE(containsAnyCaseless("", {"CW"}));
    EXPECT_FALSE(containsAnyCaseless("CO", {"CONT"}));
}

/// The plain reading of the pre-check: capitals of the text, then a search per needle.
bool containsAnyByUpperCopy(std::string text, const std::vector<std::string>& needles) {
    for (char& c : text)
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 32);
    for (const std::string& needle : needles)
        if (text.find(needle) != std::string::npos) return true;
    return false;
}

TEST(CompilerTextScan, NeedleTableAgreesWithTheUpperCaseCopyOnRandomTexts) {
    const std::vector<std::string> needles = {"CONT", "START",  "LINE",    "CW",
                                              "LA_",  "CYCLE_", "WINDOW_", "ACC_EFF"};
    const CaselessNeedles table{"CONT", "START",  "LINE",    "CW",
                                "LA_",  "CYCLE_", "WINDOW_", "ACC_EFF"};
    const std::string alphabet = "CONTSARLIEWcontsarliew_ 0123456789;(YX\xe4";
    std::mt19937 random(21);
    int found = 0;
    for (int round = 0; round < 20000; ++round) {
        std::string text(random() % 24, ' ');
        for (char& c : text)
            c = alphabet[random() % alphabet.size()];
        const bool expected = containsAnyByUpperCopy(text, needles);
        ASSERT_EQ(table.foundIn(text), expected) << text;
        found += expected;
    }
    EXPECT_GT(found, 100);  // both answers occur
    EXPECT_LT(found, 19900);
}

/// The names forEachName visits, read by `scan`, as "begin-end" pairs.
template <typename Scan>
std::string visitedNames(std::string_view text, Scan scan) {
    std::string visited;
    scan(text, [&](std::size_t begin, std::size_t end) {
        visited += std::to_string(begin) + "-" + std::to_string(end) + " ";
    });
    return visited;
}

TEST(CompilerTextScan, NameScanWithoutBracketsAgreesWithTheGeneralReading) {
    const std::string alphabet = "FEDCOLX_19 .*@=+;()[]";
    std::mt19937 random(6);
    int withBrackets = 0;
    for (int round = 0; round < 20000; ++round) {
        std::string text(random() % 30, ' ');
        for (char& c : text)
            c = alphabet[random() % (round % 2 ? alphabet.size() : alphabet.size() - 4)];
        const auto anyText = [](std::string_view t, auto visit) { forEachNameAnyText(t, visit); };
        const auto dispatched = [](std::string_view t, auto visit) { forEachName(t, visit); };
        ASSERT_EQ(visitedNames(text, dispatched), visitedNames(text, anyText)) << text;
        withBrackets += hasBracketBefore(text, commentOffset(text));
    }
    EXPECT_GT(withBrackets, 1000);  // both readings are exercised
    EXPECT_LT(withBrackets, 19000);
}

TEST(CompilerTextScan, RoundHalfAwayIsLlroundOverTheWholeCoordinateRange) {
    std::mt19937_64 random(4);
    std::uniform_real_distribution<double> exponent(-8.0, 18.0);
    for (int round = 0; round < 200000; ++round) {
        double value = std::pow(10.0, exponent(random)) * (random() % 2 ? 1.0 : -1.0);
        if (round % 4 == 1) value = std::floor(value) + 0.5;  // exact halves
        if (round % 4 == 2) value = std::nextafter(std::floor(value) + 0.5, 0.0);
        if (std::fabs(value) > 1e18) continue;
        ASSERT_EQ(roundHalfAway(value), std::llround(value)) << value;
    }
    for (double value : {0.0, -0.0, 0.5, -0.5, 0.49999999999999994, -0.49999999999999994,
                         4503599627370495.5, -4503599627370495.5, 4503599627370497.0, 1e18, -1e18})
        EXPECT_EQ(roundHalfAway(value), std::llround(value)) << value;
}

/// A count of 0.0001 steps written by printf: four decimals, trailing zeros cut.
std::string ticksByPrintf(long long ticks) {
    char buffer[48];
    const unsigned long long magnitude = ticks < 0 ? 0ull - static_cast<unsigned long long>(ticks)
                                                   : static_cast<unsigned long long>(ticks);
    std::snprintf(buffer, sizeof buffer, "%s%llu.%04llu", ticks < 0 ? "-" : "", magnitude / 10000,
                  magnitude % 10000);
    std::string text(buffer);
    while (text.back() == '0')
        text.pop_back();
    if (text.back() == '.') text.pop_back();
    return text;
}

TEST(CompilerTextScan, AppendTicksWritesWhatPrintfWrites) {
    std::mt19937_64 random(9);
    for (int round = 0; round < 100000; ++round) {
        long long ticks = static_cast<long long>(random() >> (1 + random() % 63));
        if (round % 3 == 0) ticks = -ticks;
        if (round % 5 == 0)
            ticks = ticks / 10000 * 10000 + static_cast<long long>(random() % 3) * 10;
        std::string out = "X";
        appendTicks(out, ticks);
        ASSERT_EQ(out, "X" + ticksByPrintf(ticks)) << ticks;
    }
    for (long long ticks : {0ll, 1ll, -1ll, 10000ll, -10000ll, 12340ll, 100000000000000000ll}) {
        std::string out;
        appendTicks(out, ticks);
        EXPECT_EQ(out, ticksByPrintf(ticks)) << ticks;
    }
}

TEST(CompilerTextScan, LookAheadWordStillReportedAfterPreCheck) {
    // LA_OFF alone must reach the look-ahead pass (the pre-check sees "LA_").
    CompilerOptions options;
    options.compilerActive = true;
    const CompileResult result = Compiler().compile("N0001 G1 X10 F100\nN0002 LA_OFF\n", options);
    ASSERT_EQ(result.status, CompileStatus::Error);
    bool found = false;
    for (const CompilerError& e : result.errors)
        found = found || e.code == "LA_OFF_WITHOUT_ON";
    EXPECT_TRUE(found);
}

TEST(CompilerTextScan, GneKeywordStillReportedAfterPreCheck) {
    // END_CONT without CONT must reach the GNE pass (the pre-check sees "CONT").
    CompilerOptions options;
    options.compilerActive = true;
    const CompileResult result = Compiler().compile("N0001 G1 X10 F100\nN0002 END_CONT\n", options);
    ASSERT_EQ(result.status, CompileStatus::Error);
    bool found = false;
    for (const CompilerError& e : result.errors)
        found = found || e.code == "GNE_END_CONT_ALONE";
    EXPECT_TRUE(found);
}

TEST(CompilerTextScan, ProgramWithoutKeywordsCompilesUnchanged) {
    CompilerOptions options;
    options.compilerActive = true;
    const CompileResult result = Compiler().compile("N0001 G1 X10 Y5 F100\nN0002 X20\n", options);
    ASSERT_EQ(result.status, CompileStatus::Compiled);
    EXPECT_EQ(result.objectText,
              "N0001:0000 G1 X10 Y5 F100\nN0002:0000 X20\nN0003:0000 PROGRAMMENDE\n");
}

}  // namespace
}  // namespace mtc::core
