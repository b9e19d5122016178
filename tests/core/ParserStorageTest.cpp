// The packed block and word lists behind Program::blocks / Program::words.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ParserTestSupport.h"

using namespace mtc::core;
using namespace mtc::core::testing;

namespace {

TEST(ParserStorage, PlainWordsRoundTrip) {
    WordList list;
    Word a;
    a.kind = WordKind::Axis;
    a.letter = 'Z';
    a.axisIndex = 2;
    a.column = 17;
    a.number = -36.15;
    list.push_back(a);
    const Word back = list[0];
    EXPECT_EQ(back.kind, WordKind::Axis);
    EXPECT_EQ(back.letter, 'Z');
    EXPECT_EQ(back.axisIndex, 2);
    EXPECT_EQ(back.column, 17);
    EXPECT_EQ(back.number, -36.15);
    EXPECT_EQ(back.expr, -1);
    EXPECT_EQ(list.memoryBytes(), 8u * 1);  // packed, no side table
}

TEST(ParserStorage, WordsThatNeedTheSideTable) {
    WordList list;
    Word jump;
    jump.kind = WordKind::Jump;
    jump.jump = JumpKind::BES;
    jump.text = TextSpan{4, 3};
    jump.eventProcess = 1;
    jump.eventNumber = 15;
    list.push_back(jump);
    Word big;
    big.kind = WordKind::T;
    big.column = 3;
    big.number = 1e12;
    list.push_back(big);
    Word far;
    far.kind = WordKind::F;
    far.column = 300;  // beyond the 8-bit column
    far.number = 2;
    list.push_back(far);
    Word negativeZero;
    negativeZero.kind = WordKind::Axis;
    negativeZero.letter = 'X';
    negativeZero.column = 1;
    negativeZero.number = -0.0;
    list.push_back(negativeZero);
    EXPECT_EQ(list[0].jump, JumpKind::BES);
    EXPECT_EQ(list[0].eventNumber, 15);
    EXPECT_EQ(list[0].text.length, 3u);
    EXPECT_EQ(list[1].number, 1e12);
    EXPECT_EQ(list[2].column, 300);
    EXPECT_TRUE(std::signbit(list[3].number));
}

TEST(ParserStorage, SetReplacesWords) {
    WordList list;
    Word w;
    w.kind = WordKind::G;
    w.column = 1;
    w.number = 1;
    list.push_back(w);
    list.push_back(w);
    Word command;
    command.kind = WordKind::Command;
    command.text = TextSpan{0, 3};
    list.set(0, command);
    w.number = 3;
    list.set(1, w);
    EXPECT_EQ(list[0].kind, WordKind::Command);
    EXPECT_EQ(list[1].number, 3);
    list.set(0, w);  // extended slot reused
    EXPECT_EQ(list[0].kind, WordKind::G);
    EXPECT_EQ(list[0].number, 3);
    int count = 0;
    for (const Word& each : list)
        count += each.kind == WordKind::G;
    EXPECT_EQ(count, 2);
}

TEST(ParserStorage, BlocksRoundTripAndSet) {
    BlockList list;
    Block plain;
    plain.firstWord = 10;
    plain.wordCount = 4;
    plain.number = 9999;
    plain.line = 123456;
    plain.lineCount = 2;
    plain.flags = kBlockSkip;
    plain.sourceText = TextSpan{1000, 40};
    list.push_back(plain);
    Block labelled = plain;
    labelled.label = TextSpan{1001, 5};
    labelled.subNumber = 3;
    list.push_back(labelled);
    list.push_back(plain);
    EXPECT_EQ(list[0].number, 9999);
    EXPECT_EQ(list[0].line, 123456u);
    EXPECT_EQ(list[0].lineCount, 2);
    EXPECT_EQ(list[0].sourceText.length, 40u);
    EXPECT_EQ(list[1].label.length, 5u);
    EXPECT_EQ(list[1].subNumber, 3);
    EXPECT_TRUE(list[2].label.empty());
    EXPECT_EQ(list.numberAt(1), 9999);
    list.set(2, labelled);
    list.set(1, plain);
    EXPECT_TRUE(list[1].label.empty());
    EXPECT_EQ(list[2].subNumber, 3);
    Block huge = plain;
    huge.sourceText = TextSpan{0, 1u << 20};
    huge.lineCount = 500;
    list.push_back(huge);
    EXPECT_EQ(list.back().sourceText.length, 1u << 20);
    EXPECT_EQ(list.back().lineCount, 500);
}

TEST(ParserStorage, ProgramStaysSmall) {
    std::string text;
    for (int i = 0; i < 20000; ++i)
        text += "N" + std::to_string(1000 + i % 9000) + " G1 X12.345 Y-3.5 F2000\n";
    Program p = parse(text);
    ASSERT_TRUE(p.diagnostics.empty());
    EXPECT_EQ(p.words.size(), 80000u);
    double ratio = static_cast<double>(p.memoryBytes()) / static_cast<double>(text.size());
    EXPECT_LT(ratio, 3.0);
}

}  // namespace
