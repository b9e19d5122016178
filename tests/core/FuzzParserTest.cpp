// Fuzz-style robustness: thousands of random and mutated programs (fixed
// seed, bounded run time) must give diagnostics and a consistent Program,
// never a crash, a hang or an out-of-range index.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "ParserTestSupport.h"
#include "cnc_core/program/DatFile.h"

using namespace mtc::core;
using namespace mtc::core::testing;

namespace {

/// Our own corpus of valid constructs: mutations start from these.
const std::vector<std::string> kCorpus = {
    "iMTc/000001/01.00/0000000100/01.01.2024/12:00:00/N1010005.DAT/1\n"
    "%NPG:1:01:0:005\n!01.00\n*fuzz seed\n%NPG\n"
    "N0000 G0 G90 G54 X0 Y0 Z50 S1200 M3\n"
    "N0001 : T7 BSR .TOOL\n"
    "N0002 G1 X12.345 Y-3.5 F2000\n"
    "N0003 G2 X20 Y0 I10 J0\n"
    "N0004 @100=M(5)-1 BMI .SKIP\n"
    "N0005 M=M(5) BRA .SKIP\n"
    "N0006 .SKIP G4 F.2\n"
    "N0007 PROGRAMMENDE\n",
    "%MAC:0:03:0:019\n*cycle\n%MAC\n%CHBEGIN%\n%V% @141 INT[1,2] direction\n"
    "%N% BSR .*CYC ;call\n%CHEND%\n"
    "N0000 .*CYC\nN0001 MTD(180,,,1)=@141\nN0002 G53 G0 Z2=@142\nN0003 RTS\n",
    "N0010 G20 Z0 C0 X2=0 G32 RI=80\nN0011 Y1 25 Z1-42 S2 3000\n"
    "N0012 G0 G17 X-0.1\n      Y3.4 S1 3000 M3 ;continued\n"
    "N0013 BES .BP1 1:15\nAXD (X:S-0-0104)=7000\n.BP1\nJMP @2\nJEV 5 1:3\n",
    "DEFINE FAST AS G01 F15000\nFAST X5\nTL_RADIUS[1,1]=2.5\nLA_ON\nG1 X1 CF2\nLA_OFF\n"
    "@1:120=(@1+2)*MTD(60,,4)-SPC/TIME+S2-T+E+G(1)\nT=MTD(60,,,5) MTP MRY MQ12 QQ=@3\n"
    "/N0020 (text) [more] ;comment\n",
};

const char kAlphabet[] =
    "NGMXYZIJKSTFQEDUVWABCRH0123456789 .:;@=+-*/()[],_\n\n\n      \t\r\x01\xff"
    "BRASPCMTDRIPROGRAMMENDE%*";

std::string randomText(std::mt19937& rng, std::size_t length) {
    std::uniform_int_distribution<int> pick(0, static_cast<int>(sizeof kAlphabet) - 2);
    std::string text;
    for (std::size_t i = 0; i < length; ++i)
        text += kAlphabet[pick(rng)];
    return text;
}

std::string randomBytes(std::mt19937& rng, std::size_t length) {
    std::uniform_int_distribution<int> byte(0, 255);
    std::string text;
    for (std::size_t i = 0; i < length; ++i)
        text += static_cast<char>(byte(rng));
    return text;
}

std::string mutate(std::mt19937& rng, std::string text) {
    std::uniform_int_distribution<int> edits(1, 8);
    int count = edits(rng);
    for (int e = 0; e < count && !text.empty(); ++e) {
        std::uniform_int_distribution<std::size_t> at(0, text.size() - 1);
        std::size_t p = at(rng);
        switch (rng() % 6) {
            case 0:
                text.erase(p, 1 + rng() % 8);
                break;
            case 1:
                text.insert(p, randomText(rng, 1 + rng() % 6));
                break;
            case 2:
                text[p] = static_cast<char>(rng() % 256);
                break;
            case 3:
                text.insert(p, text.substr(at(rng), 1 + rng() % 40));
                break;
            case 4:
                text.insert(p, std::string(1 + rng() % 100, "((([[@-"[rng() % 7]));
                break;
            default:
                std::swap(text[p], text[at(rng)]);
                break;
        }
    }
    return text;
}

/// Every index and span in `p` lies inside its vectors and its source.
void checkConsistent(const Program& p, const std::string& input) {
    ASSERT_EQ(p.source, input);
    std::size_t sourceSize = p.source.size();
    auto spanOk = [&](TextSpan s) {
        return s.offset + static_cast<std::size_t>(s.length) <= sourceSize;
    };
    std::size_t expectedWord = 0;
    for (std::size_t b = 0; b < p.blocks.size(); ++b) {
        const Block& block = p.blocks[b];
        ASSERT_EQ(block.firstWord, expectedWord);
        expectedWord += block.wordCount;
        ASSERT_LE(expectedWord, p.words.size());
        ASSERT_TRUE(spanOk(block.sourceText) && spanOk(block.label) && spanOk(block.comment));
        ASSERT_GE(block.line, 1u);
    }
    ASSERT_EQ(expectedWord, p.words.size());
    auto nodeOk = [&](std::int32_t n) {
        return n >= -1 && n < static_cast<std::int32_t>(p.expressions.size());
    };
    for (std::size_t i = 0; i < p.words.size(); ++i) {
        const Word w = p.words[i];
        ASSERT_TRUE(nodeOk(w.expr) && nodeOk(w.target));
        ASSERT_TRUE(spanOk(w.text) && spanOk(w.args));
    }
    for (std::size_t i = 0; i < p.expressions.size(); ++i) {
        const ExprNode& n = p.expressions[i];
        for (std::int32_t child : {n.a, n.b, n.c, n.d})
            ASSERT_TRUE(child >= -1 && child < static_cast<std::int32_t>(i));
    }
    for (const auto& [name, index] : p.labels)
        ASSERT_LT(index, p.blocks.size());
    for (const auto& d : p.diagnostics.items()) {
        ASSERT_FALSE(d.code.empty());
        ASSERT_FALSE(d.message.empty());
        ASSERT_GE(d.where.line, 0);
        ASSERT_GE(d.where.column, 0);
    }
    ASSERT_LE(p.diagnostics.size(), 1001u);
}

TEST(FuzzParser, RandomAndMutatedProgramsGiveDiagnosticsNotCrashes) {
    std::mt19937 rng(20240611u);
    // A fixed number of programs: the result does not depend on the
    // machine's speed (libFuzzer's campaign, docs/FUZZING.md, runs longer).
    int programs = 0, withDiagnostics = 0;
    for (; programs < 3000; ++programs) {
        std::string input;
        switch (programs % 4) {
            case 0:
                input = randomText(rng, rng() % 400);
                break;
            case 1:
                input = randomBytes(rng, rng() % 300);
                break;
            default:
                input = mutate(rng, kCorpus[rng() % kCorpus.size()]);
                break;
        }
        Program p = DatFile::parse(input, "N1010005.DAT");
        checkConsistent(p, input);
        if (::testing::Test::HasFatalFailure()) {
            ADD_FAILURE() << "program " << programs << " input:\n" << input;
            return;
        }
        if (!p.diagnostics.empty()) ++withDiagnostics;
    }
    EXPECT_EQ(programs, 3000);
    EXPECT_GT(withDiagnostics, programs / 2);  // garbage does get reported
}

TEST(FuzzParser, CorpusProgramsAreClean) {
    for (const std::string& text : kCorpus) {
        Program p = parse(text);
        for (const auto& d : p.diagnostics.items())
            EXPECT_EQ(d.severity, Severity::Warning) << formatDiagnostic(d);
        checkConsistent(p, text);
    }
}

}  // namespace
