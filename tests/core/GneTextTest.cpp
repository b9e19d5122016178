// GNE keyword text <-> model: round trip, diagnostics with line, fuzz.

#include <gtest/gtest.h>

#include <random>

#include "cnc_core/contour/GneExpansion.h"
#include "cnc_core/contour/GneSchema.h"
#include "cnc_core/contour/GneText.h"

namespace mtc::core::gne {
namespace {

const char* kTurning =
    "WINDOW_01 (-80, 2, 40)\n"
    "CONT (1, FINAL)\n"
    "START Z0 X0\n"
    "LINE Z0 X15\n"
    "CF 1\n"
    "LINE Z-20 X15 A180\n"
    "RELIEF E R0.6 T0.2\n"
    "LINE Z-20 X25\n"
    "RD 2\n"
    "LINE A180 L10\n"
    "CW Z-40 X35 R10 TAN ALT1\n"
    "CCW Z-50 X35 K-45 I35\n"
    "LINE Z-60 X38.5 A160.5\n"
    "END_CONT\n"
    "CONT (2, RAW)\n"
    "START Z2 X40\n"
    "LINE Z-80 X40\n"
    "END_CONT\n"
    "FORM_20 (3, -30, 25, 4, 2)\n"
    "CYCLE_11 (1, 1, 0.3, 1200, 3, 0.4, 80, 95, 1, 2, 0.5, 0.2)\n"
    "CYCLE_12 (1, 1, 0.2, , 3, 0.4, , , , 0.2)\n"
    "CYCLE_10 (1, 2, 0.1)\n";

const char* kMilling =
    "WINDOW_02 (0, 0, 120, 80, 0, -20)\n"
    "FORM_50 (1, 10, 10, 40, 10, 8)\n"
    "FORM_51 (2, 60, 40, 20, 0, 90, 6)\n"
    "FORM_52 (3, 90, 20, 8)\n"
    "FORM_53 (4, 90, 60, 12, 6)\n"
    "FORM_54 (5, 10, 70, 5, 0, \"MTC 200\")\n"
    "FORM_55 (6, 60, 40, 30, 120, 4, \"INDRAMAT\")\n"
    "FORM_56 (7, 5, 5, 115, 75, 5)\n"
    "FORM_57 (8, 30, 40, 20, 10, 30, 2)\n"
    "CYCLE_40 (7, 3, 800, 2000, 5, 1, 2, -5, 200)\n"
    "CYCLE_40 (5, 6, 300, , 1, 0, 2, -0.3)\n";

TEST(GneText, RoundTripIsStable) {
    for (const char* text : {kTurning, kMilling}) {
        GneDocument doc = readGne(text);
        ASSERT_TRUE(doc.ok()) << doc.diagnostics[0].line << ": " << doc.diagnostics[0].message;
        const std::string written = writeGne(doc);
        EXPECT_EQ(written, text);  // the texts above are written in canonical form
        GneDocument again = readGne(written);
        ASSERT_TRUE(again.ok());
        EXPECT_EQ(writeGne(again), written);
    }
}

TEST(GneText, ReadsElementsIntoTheModel) {
    GneDocument doc = readGne(kTurning);
    ASSERT_EQ(doc.items.size(), 7u);
    const Contour& c = doc.items[1].contour;
    EXPECT_EQ(c.number, 1);
    EXPECT_FALSE(c.raw);
    EXPECT_EQ(c.plane, GnePlane::Turning);
    ASSERT_EQ(c.elements.size(), 11u);
    const ContourElement& cw = c.elements[8];
    EXPECT_EQ(cw.kind, ElementKind::ArcCW);
    EXPECT_EQ(*cw.end[0], -40);  // Z = 1st plane axis
    EXPECT_EQ(*cw.end[1], 35);
    EXPECT_EQ(*cw.radius, 10);
    EXPECT_TRUE(cw.tangent);
    EXPECT_EQ(cw.alternative, 1);
    EXPECT_EQ(cw.line, 11u);
    EXPECT_EQ(c.elements[4].reliefForm, 'E');
    EXPECT_TRUE(doc.items[2].contour.raw);
    const GneCall& rough = doc.items[4].call;
    EXPECT_EQ(rough.keyword, "CYCLE_11");
    EXPECT_EQ(rough.values.size(), 12u);
    const GneCall& residual = doc.items[5].call;
    EXPECT_FALSE(residual.values[3].has_value());
    EXPECT_EQ(paramValue(*findCallSpec("CYCLE_12"), residual, kCycleCornerAngle), 80.0);
}

TEST(GneText, AcceptsBlockNumbersCommentsAndOtherBlocks) {
    GneDocument doc = readGne(
        "N0010 G0 X100 ;no GNE\n"
        "N0011 WINDOW_01 (-50, 0, 20) ;blank\n"
        "N0012 CONT (4)\n"
        "N0013 START Z0 X0\n"
        "N0014:0001 LINE Z=0 X=10\n"
        "/N0015 END_CONT\n"
        "N0016 RD 2\n",
        10);
    ASSERT_TRUE(doc.ok()) << doc.diagnostics[0].message;
    ASSERT_EQ(doc.items.size(), 2u);
    EXPECT_EQ(doc.items[1].contour.line, 12u);
    EXPECT_EQ(doc.items[1].contour.endLine, 15u);
}

std::vector<std::string> codesOf(const std::string& text) {
    std::vector<std::string> codes;
    for (const GneDiagnostic& d : readGne(text).diagnostics)
        codes.push_back(std::to_string(d.line) + " " + d.code);
    return codes;
}

TEST(GneText, DiagnosticsNameLineAndProblem) {
    using V = std::vector<std::string>;
    EXPECT_EQ(codesOf("CONT (1)\nSTART Z0 X0\nEND_CONT\n"), V{"1 GNE_NO_WINDOW"});
    EXPECT_EQ(codesOf("WINDOW_01 (-5, 0, 9)\nCONT (1)\nSTART Z0 X0\n"), V{"2 GNE_CONT_NOT_CLOSED"});
    EXPECT_EQ(codesOf("WINDOW_01 (-5, 0, 9)\nCONT (1)\nLINE Z0 X0\nEND_CONT\n"),
              (V{"3 GNE_START_POSITION", "2 GNE_NO_START"}));
    EXPECT_EQ(codesOf("WINDOW_01 (-5, 0, 9)\nCONT (1)\nSTART Z0 X0\nLINE Y5\nEND_CONT\n"),
              V{"4 GNE_BAD_WORD"});
    EXPECT_EQ(codesOf("WINDOW_01 (-5, 0, 9)\nCONT (1)\nSTART Z0 X0\nLINE Z1 Z2\nEND_CONT\n"),
              V{"4 GNE_WORD_TWICE"});
    EXPECT_EQ(codesOf("WINDOW_01 (-5, 0, 9)\nCONT (1)\nSTART Z0 X0\nG1 X5\nEND_CONT\n"),
              V{"4 GNE_NOT_AN_ELEMENT"});
    EXPECT_EQ(codesOf("LINE Z5\n"), V{"1 GNE_ELEMENT_OUTSIDE_CONT"});
    EXPECT_EQ(codesOf("END_CONT\n"), V{"1 GNE_END_CONT_ALONE"});
    EXPECT_EQ(codesOf("WINDOW_02 (0, 0, 9, 9)\nFORM_99 (1)\n"), V{"2 GNE_UNKNOWN_KEYWORD"});
    EXPECT_EQ(codesOf("WINDOW_02 (0, 0, 9, 9)\nFORM_52 (1, 2, 3)\n"), V{"2 GNE_PARAMETER"});
    EXPECT_EQ(codesOf("WINDOW_02 (0, 0, 9, 9)\nFORM_52 (1, 2, 3, -4)\n"), V{"2 GNE_PARAMETER"});
    EXPECT_EQ(codesOf("WINDOW_02 (0, 0, 9, 9)\nFORM_52 (1, 2, 3, x)\n"), V{"2 GNE_BAD_NUMBER"});
    EXPECT_EQ(codesOf("WINDOW_02 (0, 0, 9, 9)\nFORM_52 (1, 2, 3, 4, 5)\n"), V{"2 GNE_TOO_MANY"});
    EXPECT_EQ(codesOf("WINDOW_02 (0, 0, 9, 9)\nFORM_52 1, 2, 3, 4\n"), V{"2 GNE_SYNTAX"});
    EXPECT_EQ(codesOf("WINDOW_02 (0, 0, 9, 9)\nFORM_20 (1, 2, 3, 4, 1)\n"), V{"2 GNE_WRONG_PLANE"});
    EXPECT_EQ(codesOf("WINDOW_02 (0, 0, 9, 9)\nFORM_54 (1, 2, 3, 4)\n"), V{"2 GNE_TEXT_MISSING"});
    EXPECT_EQ(codesOf("FORM_52 (1, 2, 3, 4)\n"), V{"1 GNE_NO_WINDOW"});
    EXPECT_EQ(codesOf("WINDOW_01 (-5, 0, 9)\nCONT (1)\nSTART Z0 X0\nRD -1\nEND_CONT\n"),
              V{"4 GNE_BAD_NUMBER"});
    EXPECT_EQ(codesOf("WINDOW_01 (-5, 0, 9)\nCONT (0, HALF)\nSTART Z0 X0\nEND_CONT\n"),
              (V{"2 GNE_CONT_NUMBER", "2 GNE_CONT_KIND"}));
}

TEST(GneText, ValuesRoundTripExactly) {
    for (double v : {0.1, -0.3, 1.0 / 3.0, 123456.789, -1e-7, 2.5e-5})
        EXPECT_EQ(std::stod(formatValue(v)), v);
    EXPECT_EQ(formatValue(0.1), "0.1");
    EXPECT_EQ(formatValue(-0.0), "0");
    // Plain decimals, never an exponent: the reader takes no exponent, so a
    // tiny value read from the text must be written the same way.
    EXPECT_EQ(formatValue(1e-10), "0.0000000001");
    EXPECT_EQ(formatValue(-2.5e-5), "-0.000025");
    EXPECT_EQ(formatValue(1e7), "10000000");
}

TEST(GneText, ATinyValueReadsBackAfterWriting) {  // fuzz finding gne 26f6fef
    const GneDocument doc = readGne("WINDOW_02 (0, 0, 100, 70, 0, -15)\n"
                                    "FORM_51 (2, 60, 35, 20, 0, 0.0000000001, 5)\n");
    ASSERT_TRUE(doc.ok());
    const std::string written = writeGne(doc);
    const GneDocument again = readGne(written);
    EXPECT_TRUE(again.ok()) << written;
    EXPECT_EQ(writeGne(again), written);
}

/// Random edits of valid GNE texts: reading, writing, solving and expanding
/// never crash or hang, and whatever reads without error writes back stably.
TEST(GneText, FuzzNeverCrashes) {
    std::mt19937 random(20261121);
    const std::string alphabet = "0123456789.-+ ,()=;\"XYZIKJARLWTUEFN_\n";
    const std::vector<std::string> seeds = {kTurning, kMilling};
    int clean = 0;
    for (int round = 0; round < 3000; ++round) {
        std::string text = seeds[static_cast<std::size_t>(round) % seeds.size()];
        const int edits = 1 + static_cast<int>(random() % 6);
        for (int e = 0; e < edits && !text.empty(); ++e) {
            const std::size_t at = random() % text.size();
            switch (random() % 3) {
                case 0:
                    text[at] = alphabet[random() % alphabet.size()];
                    break;
                case 1:
                    text.erase(at, 1 + random() % 8);
                    break;
                default:
                    text.insert(at, 1, alphabet[random() % alphabet.size()]);
                    break;
            }
        }
        GneDocument doc = readGne(text);
        for (const GneDiagnostic& d : doc.diagnostics)
            EXPECT_FALSE(d.message.empty());
        GneExpansion expansion = expandGne(doc);
        for (const GneDiagnostic& d : expansion.diagnostics)
            EXPECT_GT(d.line, 0u) << d.message;
        if (!doc.ok()) continue;
        ++clean;
        const std::string written = writeGne(doc);
        EXPECT_EQ(writeGne(readGne(written)), written);
    }
    EXPECT_GT(clean, 100);  // the fuzzer also reaches valid documents
}

}  // namespace
}  // namespace mtc::core::gne
