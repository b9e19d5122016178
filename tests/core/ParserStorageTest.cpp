// The packed block and word lists behind Program::blocks / Program::words.
#include <gtest/gtest.h>

#include <random>

#include <cmath>
#include <string>
#include <vector>

#include "ParserTestSupport.h"
#include "tests/support/ProgramDifference.h"

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
    EXPECT_EQ(list.memoryBytes(), 5u * 1);  // narrow (slot and column), no side table
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

TEST(ParserStorage, WideWordsBesideNarrowOnes) {
    WordList list;
    // Narrow: |mantissa| < 2^26; wide: larger ones, and every head after
    // the 30th (kind, letter, axis index, scale).
    ASSERT_TRUE(list.tryPushNumber(WordKind::Axis, 'X', 0, 5, 67108863, 3));
    ASSERT_TRUE(list.tryPushNumber(WordKind::Axis, 'X', 0, 6, -67108864, 3));
    ASSERT_TRUE(list.tryPushNumber(WordKind::Axis, 'X', 0, 7, 67108864, 3));
    ASSERT_TRUE(list.tryPushNumber(WordKind::F, 'F', 0, 8, -2147483647, 0));
    EXPECT_EQ(list.memoryBytes(), 5u * 4 + 8u * 2);
    for (int i = 0; i < 70; ++i)
        ASSERT_TRUE(list.tryPushNumber(WordKind::Axis, static_cast<char>('A' + i % 26),
                                       static_cast<std::uint8_t>(i / 26), 9, i, 1));
    EXPECT_EQ(list[0].number, 67108.863);
    EXPECT_EQ(list[1].number, -67108.864);
    EXPECT_EQ(list[2].number, 67108.864);
    EXPECT_EQ(list[0].column, 5);
    EXPECT_EQ(list[1].column, 6);
    EXPECT_EQ(list[3].number, -2147483647.0);
    EXPECT_EQ(list[2].column, 7);
    for (int i = 0; i < 70; ++i) {
        const Word w = list[4 + static_cast<std::size_t>(i)];
        EXPECT_EQ(w.letter, 'A' + i % 26);
        EXPECT_EQ(w.axisIndex, i / 26);
        EXPECT_EQ(w.number, i / 10.0);
        EXPECT_EQ(w.column, 9);
    }
    list.truncate(2);  // drops the wide forms of the dropped words too
    EXPECT_EQ(list.size(), 2u);
    EXPECT_EQ(list[1].number, -67108.864);
    ASSERT_TRUE(list.tryPushNumber(WordKind::Axis, 'Y', 0, 4, 5000000, 4));
    EXPECT_EQ(list[2].number, 500.0);
    list.truncate(2);
    // Narrow slots written in place, as the parser's fast path does.
    EXPECT_EQ(list.plainCodeAt(WordList::codeKey('X', 3)),
              WordList::kWideCode);  // not asked for yet
    const WordList::Packed code = list.plainCode(WordKind::Axis, 'X', 3);
    ASSERT_NE(code, WordList::kWideCode);
    EXPECT_EQ(list.plainCodeAt(WordList::codeKey('X', 3)), code);  // known from now on
    // all 30 heads taken: a new one has no narrow form
    EXPECT_EQ(list.plainCode(WordKind::G, 'G', 0), WordList::kWideCode);
    EXPECT_EQ(list.plainCodeAt(WordList::codeKey('G', 0)), WordList::kWideCode);
    list.makeSpare();
    WordList::Packed* out = list.spareBegin();
    std::uint8_t* columns = list.spareColumns();
    ASSERT_GE(list.spareEnd() - out, 1);
    *out++ = WordList::narrowSlot(code, 3);
    *columns++ = 3;
    if (out == list.spareEnd()) {
        list.endAt(out);
        list.makeSpare();
        out = list.spareBegin();
        columns = list.spareColumns();
    }
    *out++ = WordList::narrowSlot(code, -67108863);
    *columns++ = 255;
    list.endAt(out);
    EXPECT_EQ(list.size(), 4u);
    EXPECT_EQ(list[2].letter, 'X');
    EXPECT_EQ(list[2].column, 3);
    EXPECT_EQ(list[3].number, -67108.863);
    EXPECT_EQ(list[3].column, 255);
    EXPECT_EQ(list[2].number, 0.003);
}

TEST(ParserStorage, NumberWordsOfEveryForm) {
    WordList list;
    ASSERT_TRUE(list.tryPushNumber(WordKind::Axis, 'Y', 2, 12, -35, 1));     // narrow
    ASSERT_TRUE(list.tryPushNumber(WordKind::F, 'F', 0, 40, 250000000, 2));  // wide
    ASSERT_TRUE(list.tryPushNumber(WordKind::G, 'G', 0, 1, 0, 0));           // narrow
    Word sum;
    sum.kind = WordKind::Axis;
    sum.letter = 'X';
    sum.column = 7;
    sum.expr = 3;
    list.push_back(sum);  // extended
    NumberWord w;
    ASSERT_TRUE(list.readNumber(0, w));
    EXPECT_EQ(w.kind, WordKind::Axis);
    EXPECT_EQ(w.letter, 'Y');
    EXPECT_EQ(w.axisIndex, 2);
    EXPECT_EQ(w.column, 12);
    EXPECT_EQ(w.expr, -1);
    EXPECT_EQ(w.number, -3.5);
    ASSERT_TRUE(list.readNumber(1, w));
    EXPECT_EQ(w.kind, WordKind::F);
    EXPECT_EQ(w.column, 40);
    EXPECT_EQ(w.number, 2500000.0);
    ASSERT_TRUE(list.readNumber(2, w));
    EXPECT_EQ(w.kind, WordKind::G);
    EXPECT_EQ(w.number, 0.0);
    EXPECT_FALSE(list.readNumber(3, w));
    EXPECT_EQ(list[3].expr, 3);
    for (std::size_t i = 0; i < 3; ++i) {  // the same as read() gives
        ASSERT_TRUE(list.readNumber(i, w));
        const Word whole = list[i];
        EXPECT_EQ(w.number, whole.number);
        EXPECT_EQ(w.column, whole.column);
        EXPECT_EQ(w.letter, whole.letter);
    }
    for (std::size_t i = 0; i < list.size(); ++i)  // narrow, wide and extended
        EXPECT_EQ(list.kindAt(i), list[i].kind) << i;
    list.clear();  // forgets the heads and the parser's codes
    EXPECT_EQ(list.plainCodeAt(WordList::codeKey('G', 0)), WordList::kWideCode);
    ASSERT_TRUE(list.tryPushNumber(WordKind::M, 'M', 0, 1, 30, 0));
    EXPECT_EQ(list[0].kind, WordKind::M);
}

TEST(ParserStorage, TheListKeepsEveryWordThatTurnsTheFlow) {
    // M02 / M30 and jumps among other words, in narrow, wide and extended
    // slots; the list must stay what reading every word finds through
    // appends, replacements and truncation.
    std::mt19937 random(4711);
    const WordKind kinds[] = {WordKind::Axis, WordKind::F, WordKind::G, WordKind::M,
                              WordKind::Jump};
    const char letters[] = {'X', 'F', 'G', 'M', 'B'};
    const std::int64_t mValues[] = {2, 30, 20, 300, 3, -2, -30, 3'000'000'000LL};
    const auto randomWord = [&](Word& word, std::int64_t& mantissa, unsigned& scale) {
        const unsigned pick = random() % 5;
        word = Word{};
        word.kind = kinds[pick];
        word.letter = letters[pick];
        word.column = static_cast<std::uint16_t>(1 + random() % 300);
        scale = random() % 3;
        mantissa = word.kind == WordKind::M ? mValues[random() % 8] : random() % 900;
        if (word.kind == WordKind::M && mantissa == 20) scale = 1;  // M2.0
        word.number = static_cast<double>(mantissa) / std::pow(10.0, scale);
        if (word.kind != WordKind::Jump && random() % 8 == 0) word.expr = 2;  // M=@1: no end
    };
    int turningSeen = 0;
    for (int round = 0; round < 40; ++round) {
        WordList list;
        const std::size_t size = 1 + random() % 300;
        for (std::size_t i = 0; i < size; ++i) {
            Word word;
            std::int64_t mantissa = 0;
            unsigned scale = 0;
            randomWord(word, mantissa, scale);
            if (word.kind == WordKind::Jump || word.expr >= 0 || random() % 4 == 0 ||
                !list.tryPushNumber(word.kind, word.letter, 0, word.column, mantissa, scale))
                list.push_back(word);
        }
        ASSERT_EQ(list.flowTurningWords(), flowTurningWordsReadOneByOne(list)) << round;
        for (int change = 0; change < 20; ++change) {
            Word word;
            std::int64_t mantissa = 0;
            unsigned scale = 0;
            randomWord(word, mantissa, scale);
            list.set(random() % list.size(), word);
            ASSERT_EQ(list.flowTurningWords(), flowTurningWordsReadOneByOne(list)) << round;
        }
        turningSeen += static_cast<int>(list.flowTurningWords().size());
        std::size_t keep = random() % (list.size() + 1);
        while (keep < list.size() && (list[keep].kind == WordKind::Jump || list[keep].expr >= 0))
            ++keep;  // truncate() drops appended numbers only
        bool numbersOnly = true;
        for (std::size_t i = keep; i < list.size(); ++i)
            numbersOnly = numbersOnly && list[i].kind != WordKind::Jump && list[i].expr < 0;
        if (numbersOnly) {
            list.truncate(keep);
            ASSERT_EQ(list.flowTurningWords(), flowTurningWordsReadOneByOne(list)) << round;
        }
        list.clear();
        EXPECT_TRUE(list.flowTurningWords().empty());
    }
    EXPECT_GT(turningSeen, 100);  // the rounds did meet turning words
}

TEST(ParserStorage, WordsKeptWholeBesideNumbers) {
    WordList list;
    Word sum;
    sum.kind = WordKind::Axis;
    sum.letter = 'X';
    sum.column = 7;
    sum.expr = 3;
    list.push_back(sum);  // kept whole
    ASSERT_TRUE(list.tryPushNumber(WordKind::Axis, 'Y', 0, 12, 5, 0));
    sum.expr = 4;
    sum.column = 400;
    list.push_back(sum);
    NumberWord w;
    EXPECT_FALSE(list.readNumber(0, w));
    ASSERT_TRUE(list.readNumber(1, w));
    EXPECT_EQ(w.number, 5.0);
    EXPECT_FALSE(list.readNumber(2, w));
    EXPECT_EQ(list[0].expr, 3);
    EXPECT_EQ(list[0].column, 7);
    EXPECT_EQ(list[2].expr, 4);
    EXPECT_EQ(list[2].column, 400);
    sum.expr = 9;
    list.set(0, sum);  // in its own side-table entry
    EXPECT_EQ(list[0].expr, 9);
    EXPECT_EQ(list[0].column, 400);
    EXPECT_EQ(list[2].expr, 4);
    list.truncate(2);  // drops the last whole word too
    ASSERT_EQ(list.size(), 2u);
    sum.expr = 5;
    list.push_back(sum);
    EXPECT_EQ(list[2].expr, 5);
    EXPECT_EQ(list[0].expr, 9);
    EXPECT_EQ(list[1].number, 5.0);
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
    w.column = 7;  // a narrow word's column byte changes too
    list.set(1, w);
    EXPECT_EQ(list[0].kind, WordKind::Command);
    EXPECT_EQ(list.kindAt(0), WordKind::Command);
    EXPECT_EQ(list[1].number, 3);
    EXPECT_EQ(list[1].column, 7);
    w.column = 300;  // beyond the column byte: the whole word is kept
    list.set(1, w);
    EXPECT_EQ(list[1].column, 300);
    EXPECT_EQ(list[1].number, 3);
    w.column = 1;
    list.set(0, w);  // extended slot reused
    EXPECT_EQ(list[0].kind, WordKind::G);
    EXPECT_EQ(list.kindAt(0), WordKind::G);
    EXPECT_EQ(list.kindAt(1), WordKind::G);
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

TEST(ParserStorage, BlocksAcrossGroupsAndGaps) {
    BlockList list;
    // 200 blocks in groups of 64; block 70 lies beyond what a 16-bit delta
    // from its group's first block reaches, block 100 starts a long text.
    for (std::uint32_t i = 0; i < 200; ++i) {
        const std::uint32_t offset = i == 70 ? 1000000 : 30 * i;
        const std::uint32_t length = i == 100 ? 300 : 20;
        ASSERT_TRUE(
            list.tryPushPlain(5 * i, 5, static_cast<std::int16_t>(i), i + 1, offset, length));
    }
    for (std::uint32_t i = 0; i < 200; ++i) {
        const Block b = list[i];
        EXPECT_EQ(b.firstWord, 5 * i);
        EXPECT_EQ(b.wordCount, 5);
        EXPECT_EQ(b.number, static_cast<std::int32_t>(i));
        EXPECT_EQ(b.line, i + 1);
        EXPECT_EQ(b.sourceText.offset, i == 70 ? 1000000 : 30 * i);
        EXPECT_EQ(b.sourceText.length, i == 100 ? 300u : 20u);
        EXPECT_EQ(list.numberAt(i), static_cast<std::int32_t>(i));
    }
    Block moved = list[64];  // the first block of its group moves away
    moved.firstWord = 3;
    moved.line = 2;
    list.set(64, moved);
    EXPECT_EQ(list[64].firstWord, 3u);
    EXPECT_EQ(list[64].line, 2u);
    EXPECT_EQ(list[65].firstWord, 325u);  // the others keep their place
    moved.firstWord = 320;
    moved.line = 65;
    list.set(64, moved);  // back in the packed form
    EXPECT_EQ(list[64].firstWord, 320u);
    EXPECT_EQ(list[64].line, 65u);
}

TEST(ParserStorage, GroupsStartWithAnyKindOfBlock) {
    // A group may start with a block kept whole (a label), a packed block
    // appended by push_back, or one of tryPushPlain; clear() starts over.
    BlockList list;
    for (int round = 0; round < 2; ++round) {
        for (std::uint32_t i = 0; i < 200; ++i) {
            Block block;
            block.firstWord = 3 * i;
            block.wordCount = 3;
            block.number = static_cast<std::int32_t>(i);
            block.line = 2 * i + 1;
            block.sourceText = TextSpan{40 * i, 30};
            if (i % 64 == 0) block.label = TextSpan{40 * i + 6, 4};
            if (i % 64 == 0 || i % 64 == 1 || i == 129)
                list.push_back(block);
            else
                ASSERT_TRUE(list.tryPushPlain(3 * i, 3, static_cast<std::int16_t>(i), 2 * i + 1,
                                              40 * i, 30));
        }
        for (std::uint32_t i = 0; i < 200; ++i) {
            const Block b = list[i];
            EXPECT_EQ(b.firstWord, 3 * i);
            EXPECT_EQ(b.line, 2 * i + 1);
            EXPECT_EQ(b.sourceText.offset, 40 * i);
            EXPECT_EQ(b.label.length, i % 64 == 0 ? 4u : 0u);
            EXPECT_EQ(b.number, static_cast<std::int32_t>(i));
        }
        EXPECT_EQ(list.memoryBytes() > 0, true);
        list.clear();
        EXPECT_TRUE(list.empty());
    }
    // a block beyond 255 words or bytes of text is kept whole
    ASSERT_TRUE(list.tryPushPlain(0, 256, 1, 1, 0, 20));
    ASSERT_TRUE(list.tryPushPlain(256, 2, 2, 2, 21, 256));
    ASSERT_TRUE(list.tryPushPlain(258, 255, 3, 3, 300, 255));
    EXPECT_EQ(list[0].wordCount, 256);
    EXPECT_EQ(list[1].sourceText.length, 256u);
    EXPECT_EQ(list[2].wordCount, 255);
    EXPECT_EQ(list[2].sourceText.length, 255u);
    EXPECT_FALSE(list.tryPushPlain(513, 1, 4, 4, 600, 65536));  // the caller keeps it whole
}

TEST(ParserStorage, ProgramStaysSmall) {
    std::string text;
    for (int i = 0; i < 20000; ++i)
        text += "N" + std::to_string(1000 + i % 9000) + " G1 X12.345 Y-3.5 F2000\n";
    Program p = parse(text);
    ASSERT_TRUE(p.diagnostics.empty());
    EXPECT_EQ(p.words.size(), 80000u);
    double ratio = static_cast<double>(p.memoryBytes()) / static_cast<double>(text.size());
    // the source itself, and 5 bytes a word (slot and column) and 12 a
    // block (plus 12 per 64 blocks): 29 + 4 * 5 + 12 bytes a line of 29
    EXPECT_LT(ratio, 2.15);
}

}  // namespace
