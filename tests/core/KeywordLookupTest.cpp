// Keyword classification by lookupKeyword (a table sorted at compile time
// and searched by halves): every listed name is found with its class, names
// next to them in sort order and partial names are not keywords.
#include <gtest/gtest.h>

#include <string>

#include "cnc_core/language/Keywords.h"

using namespace mtc::core;

namespace {

TEST(KeywordLookup, EveryJumpMnemonicGivesItsJumpKind) {
    for (int k = 0; k <= static_cast<int>(JumpKind::BTE); ++k) {
        const auto kind = static_cast<JumpKind>(k);
        const KeywordInfo info = lookupKeyword(jumpName(kind));
        EXPECT_EQ(info.keywordClass, KeywordClass::Jump) << jumpName(kind);
        EXPECT_EQ(info.jump, kind) << jumpName(kind);
    }
}

TEST(KeywordLookup, ListedNamesHaveTheirClass) {
    const struct {
        const char* name;
        KeywordClass expected;
    } cases[] = {
        {"RI", KeywordClass::EffectiveRadius},
        {"MTD", KeywordClass::Mtd},
        {"SPC", KeywordClass::ReadOnly},
        {"TIME", KeywordClass::ReadOnly},
        {"PROGRAMMENDE", KeywordClass::ProgramEnd},
        {"MTP", KeywordClass::Command},
        {"TLD", KeywordClass::Command},
        {"BRJ", KeywordClass::Command},
        {"WER", KeywordClass::Command},
        {"CF", KeywordClass::CompilerCommand},
        {"RD", KeywordClass::CompilerCommand},
        {"ACD_COMP", KeywordClass::CompilerCommand},
        {"CYCLE_MP", KeywordClass::CompilerCommand},
        {"DEFINE", KeywordClass::CompilerRestOfBlock},
        {"CCW", KeywordClass::CompilerRestOfBlock},
        {"RELIEF", KeywordClass::CompilerRestOfBlock},
        {"FORM_12", KeywordClass::CompilerCommand},
        {"WINDOW_3", KeywordClass::CompilerCommand},
        {"FX", KeywordClass::AxisFeed},
        {"FC", KeywordClass::AxisFeed},
    };
    for (const auto& c : cases)
        EXPECT_EQ(lookupKeyword(c.name).keywordClass, c.expected) << c.name;
}

TEST(KeywordLookup, NeighboursAndPartsAreNoKeywords) {
    for (const char* name : {"", "A", "AAA", "BR", "BRAX", "BRB", "C", "CFF", "DEFIN", "DEFINES",
                             "PROGRAMMEND", "ZZZ", "TCHX", "FORM_", "FORM_1A", "FQ", "FXX", "ra"})
        EXPECT_EQ(lookupKeyword(name).keywordClass, KeywordClass::None) << name;
}

}  // namespace
