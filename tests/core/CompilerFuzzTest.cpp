// Robustness of the NC compiler: random and mutated programs built from our
// own corpus of compiler constructs (fixed seed, bounded time) must give a
// result that is consistent (status, limits of messages, line map, object
// text that parses) and never a crash or a hang.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "CompilerTestSupport.h"
#include "cnc_core/compiler/CompilerFiles.h"
#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/language/Parser.h"

using namespace mtc::core;
using namespace mtc::test;

namespace {

const std::vector<std::string> kCorpus = {
    "iMTc/000001/01.00/0000000100/01.01.2024/12:00:00/N1010007.DAT/1\n"
    "%NPG:1:01:0:007\n*fuzz\n%NPG\n"
    "N0000 DEFINE SLOW AS G1 F200\n"
    "N0001 G0 G90 G17 X0 Y0 Z5\n"
    "N0002 SLOW X40 Y0 RD4\n"
    "N0003 X40 Y30 CF=2.5\n"
    "N0004 M8\n"
    "N0005 G3 X10 Y30 I25 J30 RD 2\n"
    "N0006 G1 X0 Y0 MODF_ON(RD1)\n"
    "N0007 X-5 Y5\n"
    "N0008 MODF_OFF\n"
    "N0009 PROGRAMMENDE\n",
    "N0010 G18 G16 G1 X0 Z0 F.2\nN0011 X20 CF1\nN0012 Z-30 RD2\nN0013 X40\n"
    "N0014 G91 Z-5 RD1\nN0015 X3\nN0016 G20 X0 Z0 Y0\nN0017 G90 X5 RD1\nN0018 Z7\n",
    "N0001 G1 X0 Y0\nN0002 X10 RD=@1\nN0003 .L Y5\nN0004 BRA .L\nN0005 CF\n"
    "N0006 X=@2 CF1\nN0007 Y3 CF1 RD1\nN0008 MODF_ON(\nN0009 DEFINE AS\n",
};

const std::vector<std::string> kFragments = {
    " CF1",       " RD2",    " RD=0.5", " CF=@3",   " MODF_ON(RD1)",
    " MODF_OFF",  " G2",     " G3",     " I5 J5",   " X10",
    " Y-7.5",     " Z3",     " G91",    " G90",     " G18",
    " G20 X0 Z0", " M8",     " ;note",  " (text)",  " DEFINE A AS M3",
    " A",         " BRA .L", "\n",      "\n      ", " G1",
    " LA_ON",     " SLOW",   " @1=2",
};

std::string mutate(std::string text, std::mt19937& random) {
    std::uniform_int_distribution<int> action(0, 4);
    const int edits = std::uniform_int_distribution<int>(1, 8)(random);
    for (int e = 0; e < edits && !text.empty(); ++e) {
        std::uniform_int_distribution<std::size_t> at(0, text.size() - 1);
        const std::size_t pos = at(random);
        switch (action(random)) {
            case 0:
                text.erase(pos, std::uniform_int_distribution<std::size_t>(1, 6)(random));
                break;
            case 1:
                text.insert(pos, kFragments[std::uniform_int_distribution<std::size_t>(
                                     0, kFragments.size() - 1)(random)]);
                break;
            case 2:
                text[pos] = static_cast<char>(std::uniform_int_distribution<int>(1, 127)(random));
                break;
            case 3:
                text.insert(pos, text.substr(at(random) % text.size(), 12));
                break;
            default:
                text[pos] =
                    "0123456789.-=()@ ;XYZ"[std::uniform_int_distribution<int>(0, 20)(random)];
                break;
        }
    }
    return text;
}

std::string randomProgram(std::mt19937& random) {
    std::string text;
    const int blocks = std::uniform_int_distribution<int>(1, 40)(random);
    for (int b = 0; b < blocks; ++b) {
        text += "N" + formatFourDigits(b);
        const int words = std::uniform_int_distribution<int>(0, 4)(random);
        for (int w = 0; w < words; ++w)
            text += kFragments[std::uniform_int_distribution<std::size_t>(
                0, kFragments.size() - 1)(random)];
        text += '\n';
    }
    return text;
}

void expectConsistent(const std::string& source, const CompileResult& r) {
    EXPECT_EQ(r.status == CompileStatus::Error, r.hasErrors()) << source;
    int errors = 0;
    for (const CompilerError& e : r.errors) {
        EXPECT_LE(e.message.size(), kMaxBriefMessage);
        EXPECT_LE(e.details.size(), kMaxDetailLines);
        for (const std::string& d : e.details)
            EXPECT_LE(d.size(), kMaxDetailLength);
        errors += e.severity == Severity::Error;
    }
    EXPECT_LE(errors, 40);
    std::string identification;
    EXPECT_EQ(parseErrorFile(formatErrorFile("id", r.errors), identification).size(),
              r.errors.size());
    if (r.status != CompileStatus::Compiled) return;
    std::size_t lines = 0;
    for (char c : r.objectText)
        lines += c == '\n';
    EXPECT_EQ(lines, r.lineMap.size());
    const Program object = parseProgram(r.objectText);
    EXPECT_FALSE(object.diagnostics.hasErrors()) << source << "\n----\n" << r.objectText;
}

TEST(CompilerFuzz, RandomAndMutatedProgramsNeverCrashAndStayConsistent) {
    std::mt19937 random(20240611);
    int compiled = 0, failed = 0;
    for (int i = 0; i < 3000; ++i) {
        const std::string source =
            i % 3 == 0 ? randomProgram(random)
                       : mutate(kCorpus[static_cast<std::size_t>(i) % kCorpus.size()], random);
        const CompileResult r = compileText(source, {{"SLOW", "G1 F200"}});
        expectConsistent(source, r);
        (r.status == CompileStatus::Compiled ? compiled : failed) += 1;
        if (::testing::Test::HasFailure()) break;
    }
    EXPECT_GT(compiled, 50);
    EXPECT_GT(failed, 300);
}

TEST(CompilerFuzz, HugeAndDegenerateInputs) {
    for (const std::string& source :
         {std::string(), std::string("\n\n\n"), std::string(100000, '('), std::string(5000, 'N'),
          "N0001 MODF_ON(" + std::string(20000, 'X') + ")\n",
          "N0001 DEFINE A AS " + std::string(3000, 'M') + "\nN0002 A A A A\n",
          std::string("N0001 G1 X0 Y0\nN0002 X1e300 RD1e300\nN0003 Y-1e300\n"),
          std::string("N0001 G1 X0 Y0\nN0002 G2 X0 Y0 I0 J0 RD1\nN0003 Y1\n")}) {
        const CompileResult r = compileText(source);
        expectConsistent(source.substr(0, 200), r);
    }
}

}  // namespace
