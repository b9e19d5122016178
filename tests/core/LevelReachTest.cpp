// Which blocks one program level runs through (restart.md ):
// the straight runs between turning blocks, branches both ways, M30 ends,
// skip blocks fall through, subroutines found by their call; and, on random
// programs, the same answers as a block-by-block walk of the rule.
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "cnc_core/language/Parser.h"
#include "cnc_core/restart/LevelReach.h"
#include "cnc_core/restart/RestartRoute.h"

namespace {

using namespace mtc::core;

ProgramPtr parsed(const std::string& text) {
    ParseOptions options;
    options.programNumber = 1;
    return std::make_shared<Program>(parseProgram(text, options));
}

std::string numbered(int n, const std::string& body) {
    char id[8];
    std::snprintf(id, sizeof id, "N%04d", n % 10000);
    return std::string(id) + " " + body + "\n";
}

/// `count` plain moves, except the blocks given in `special` (index -> body).
std::string programOf(int count, const std::vector<std::pair<int, std::string>>& special) {
    std::string text;
    for (int i = 0; i < count; ++i) {
        std::string body = "G1 X" + std::to_string(i % 50) + " F500";
        for (const auto& [at, what] : special)
            if (at == i) body = what;
        text += numbered(i, body);
    }
    return text;
}

std::vector<std::uint32_t> reachedBlocks(const LevelReach& reach, std::uint32_t entry) {
    const LevelReach::BlockSet bits = reach.reachable({entry});
    std::vector<std::uint32_t> out;
    for (std::uint32_t i = 0; i < bits.size(); ++i)
        if (bits.test(i)) out.push_back(i);
    return out;
}

std::vector<bool> asVector(const LevelReach::BlockSet& bits) {
    std::vector<bool> out(bits.size());
    for (std::size_t i = 0; i < bits.size(); ++i)
        out[i] = bits.test(i);
    return out;
}

TEST(LevelReach, M30EndsTheLevelAndALabelBehindItIsOnlyReachedFromItself) {
    const ProgramPtr p = parsed(programOf(200, {{130, "M30"}, {131, ".SUB G1 X1"}, {199, "RTS"}}));
    const LevelReach reach(p);
    EXPECT_TRUE(reach.reaches({0}, 129));
    EXPECT_TRUE(reach.reaches({0}, 130));
    EXPECT_FALSE(reach.reaches({0}, 131));
    EXPECT_FALSE(reach.reaches({0}, 199));
    EXPECT_TRUE(reach.reaches({131}, 199));
    EXPECT_FALSE(reach.reaches({131}, 130));
    EXPECT_EQ(reachedBlocks(reach, 0).size(), 131u) << "blocks 0..130";
    EXPECT_FALSE(reach.reaches({0}, 200)) << "past the last block";
}

TEST(LevelReach, ABranchBackStopsTheStraightRunAtTheBlocksSeenAndEndsTheFallThrough) {
    // A loop from block 150 back to block 10 (across several 64-block words
    // of the walk's bit set); BRA does not fall through, so 151.. are dead.
    const ProgramPtr p = parsed(programOf(300, {{10, ".LOOP G1 X2"}, {150, "BRA .LOOP"}}));
    const LevelReach reach(p);
    EXPECT_EQ(reachedBlocks(reach, 0).size(), 151u);
    EXPECT_FALSE(reach.reaches({0}, 151));
    EXPECT_TRUE(reach.reaches({70}, 5 + 10)) << "from inside the loop round to its head";
    EXPECT_FALSE(reach.reaches({70}, 9)) << "the blocks before the label are not on the loop";
    EXPECT_TRUE(reach.reaches({200}, 299));
}

TEST(LevelReach, AConditionalBranchGoesBothWaysAndASkippedM30FallsThrough) {
    const ProgramPtr p = parsed(programOf(
        260, {{20, "BEQ .ON"}, {21, "M30"}, {100, "/M30"}, {180, ".ON G1 X3"}, {200, "M30"}}));
    const LevelReach reach(p);
    EXPECT_TRUE(reach.reaches({0}, 21));
    EXPECT_FALSE(reach.reaches({0}, 22)) << "M30 ends the branch not taken";
    EXPECT_TRUE(reach.reaches({0}, 180)) << "the branch taken";
    EXPECT_FALSE(reach.reaches({0}, 201));
    EXPECT_TRUE(reach.reaches({22}, 150)) << "a skip block may fall through its M30";
    EXPECT_EQ(reachedBlocks(reach, 22).size(), 200u - 22u + 1u);
}

TEST(LevelReach, TheSubroutineOfABlockIsTheCalledLabelThatReachesIt) {
    const ProgramPtr p =
        parsed(programOf(220, {{5, "BSR .CUT"}, {6, "M30"}, {150, ".CUT G1 X4"}, {210, "RTS"}}));
    const LevelReach reach(p);
    EXPECT_FALSE(reach.reaches({0}, 180));
    const auto sub = reach.subroutineOf(180);
    ASSERT_TRUE(sub.has_value());
    EXPECT_EQ(sub->label, "CUT");
    EXPECT_EQ(sub->labelBlock, 150u);
    EXPECT_EQ(sub->callBlock, 5u);
    EXPECT_FALSE(reach.subroutineOf(100).has_value()) << "dead code after M30, called by nobody";
}

/// The rule of R-023 block by block, as the walk did before R-034: the
/// reference the straight runs are compared with.
std::vector<bool> referenceReach(const Program& p, std::uint32_t entry) {
    std::vector<bool> seen(p.blocks.size(), false);
    std::vector<std::uint32_t> open{entry};
    seen[entry] = true;
    while (!open.empty()) {
        const std::uint32_t b = open.back();
        open.pop_back();
        const Block block = p.blocks[b];
        bool ends = (block.flags & kBlockProgramEnd) != 0, branch = false, stops = false;
        long label = -1;
        for (std::uint32_t w = block.firstWord; w < block.firstWord + block.wordCount; ++w) {
            const Word word = p.words[w];
            if (word.kind == WordKind::M && word.expr < 0 &&
                (word.number == 2 || word.number == 30))
                ends = true;
            if (word.kind != WordKind::Jump) continue;
            const PathStepKind step = pathStepKind(word.jump);
            stops = word.jump == JumpKind::BRA || word.jump == JumpKind::RTS ||
                    word.jump == JumpKind::RET || word.jump == JumpKind::BST ||
                    word.jump == JumpKind::JMP;
            branch = step == PathStepKind::Branch;
            if (branch) label = p.findLabel(p.text(word.text));
        }
        std::vector<std::uint32_t> next;
        const bool mayFall = (block.flags & (kBlockSkip | kBlockHasError)) != 0;
        if ((mayFall || (!ends && !stops)) && b + 1 < p.blocks.size()) next.push_back(b + 1);
        if (!ends && branch && label >= 0) next.push_back(static_cast<std::uint32_t>(label));
        for (std::uint32_t n : next)
            if (!seen[n]) seen[n] = true, open.push_back(n);
    }
    return seen;
}

/// Seed 000, 2.4 block by block: the straight flow from block 0 up to the
/// first word that stops it; an RTS there is a return without a call.
std::optional<std::uint32_t> referenceReturnWithoutCall(const Program& p) {
    for (std::uint32_t b = 0; b < p.blocks.size(); ++b) {
        const Block block = p.blocks[b];
        bool jumped = false;
        for (std::uint32_t w = block.firstWord; w < block.firstWord + block.wordCount; ++w) {
            const Word word = p.words[w];
            if (word.kind == WordKind::M && word.expr < 0 &&
                (word.number == 2 || word.number == 30))
                return std::nullopt;
            if (word.kind != WordKind::Jump || jumped) continue;
            jumped = true;
            if (word.jump == JumpKind::RTS) return b;
            if (word.jump == JumpKind::BRA || word.jump == JumpKind::RET ||
                word.jump == JumpKind::BST || word.jump == JumpKind::JMP)
                return std::nullopt;
        }
        if (block.flags & kBlockProgramEnd) return std::nullopt;
    }
    return std::nullopt;
}

std::string randomProgram(std::mt19937& random, int count) {
    const char* branches[] = {"BRA", "BEQ", "BNE", "BPL", "BMI"};
    std::string text;
    for (int i = 0; i < count; ++i) {
        std::string body;
        const int label = static_cast<int>(random() % 8);
        switch (random() % 24) {
            case 0:
                body = branches[random() % 5] + std::string(" .L") + std::to_string(label);
                break;
            case 1:
                body = "M30";
                break;
            case 2:
                body = "BSR .L" + std::to_string(label);
                break;
            case 3:
                body = random() % 4 ? "RTS" : "BNE .L" + std::to_string(label) + " RTS";
                break;
            case 4:
                body = "M3 M8 G1 X1";
                break;
            default:
                body = "G1 X" + std::to_string(i % 7) + " Y1";
        }
        const bool labelled = random() % 16 == 0 && label < 8;
        if (labelled) body = ".L" + std::to_string(label) + " " + body;
        text += (random() % 20 == 0 ? "/" : "") + numbered(i, body);
    }
    return text;
}

TEST(LevelReach, RandomProgramsReachWhatTheBlockByBlockRuleReaches) {
    std::mt19937 random(2111);
    for (int round = 0; round < 60; ++round) {
        const int count = 20 + static_cast<int>(random() % 400);
        const ProgramPtr p = parsed(randomProgram(random, count));
        ASSERT_EQ(p->blocks.size(), static_cast<std::size_t>(count));
        const LevelReach reach(p);
        for (int probe = 0; probe < 6; ++probe) {
            const auto entry = static_cast<std::uint32_t>(random() % count);
            const std::vector<bool> expected = referenceReach(*p, entry);
            ASSERT_EQ(asVector(reach.reachable({entry})), expected)
                << "round " << round << " entry " << entry;
            const auto target = static_cast<std::uint32_t>(random() % count);
            EXPECT_EQ(reach.reaches({entry}, target), bool(expected[target]));
        }
    }
}

TEST(LevelReach, AReturnBeforeAnyStopOfTheStraightFlowIsAReturnWithoutCall) {
    const auto rts = [](const std::vector<std::pair<int, std::string>>& special) {
        return LevelReach(parsed(programOf(200, special))).returnWithoutCall();
    };
    EXPECT_EQ(rts({{140, "RTS"}, {150, "M30"}}), std::optional<std::uint32_t>(140));
    EXPECT_EQ(rts({{10, "BSR .S"}, {11, "BEQ .S"}, {140, "RTS"}, {150, ".S M30"}}),
              std::optional<std::uint32_t>(140))
        << "calls and conditional branches do not stop the straight flow";
    EXPECT_EQ(rts({{70, "M30"}, {140, "RTS"}}), std::nullopt) << "M30 ends the program first";
    EXPECT_EQ(rts({{70, "BRA .E"}, {140, "RTS"}, {150, ".E M30"}}), std::nullopt);
    EXPECT_EQ(rts({{70, "JMP 2"}, {140, "RTS"}}), std::nullopt);
    EXPECT_EQ(rts({{90, "M30 RTS"}}), std::nullopt) << "the first stopping word of a block counts";
    EXPECT_EQ(rts({{90, "/RTS"}, {100, "M30"}}), std::optional<std::uint32_t>(90))
        << "a skip block's RTS counts (the operator may not skip)";
    EXPECT_EQ(rts({}), std::nullopt) << "no RTS: the flow reaches PROGRAMMENDE";
    EXPECT_EQ(rts({{90, "BEQ .S RTS"}, {100, ".S M30"}}), std::nullopt)
        << "a second jump word in a block is an error, not a return";
    EXPECT_EQ(rts({{90, "BEQ .S M30"}, {100, ".S RTS"}}), std::nullopt)
        << "an M30 after a conditional branch still ends the straight flow";
}

TEST(LevelReach, RandomProgramsFindTheReturnWithoutCallOfTheBlockByBlockRule) {
    std::mt19937 random(2407);
    int returns = 0;
    for (int round = 0; round < 200; ++round) {
        const int count = 2 + static_cast<int>(random() % 60);
        const ProgramPtr p = parsed(randomProgram(random, count));
        const std::optional<std::uint32_t> expected = referenceReturnWithoutCall(*p);
        ASSERT_EQ(LevelReach(p).returnWithoutCall(), expected) << "round " << round;
        returns += expected.has_value();
    }
    EXPECT_GT(returns, 20) << "the random programs must also start with subroutines";
}

}  // namespace
