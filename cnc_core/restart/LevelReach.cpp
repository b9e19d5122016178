#include "cnc_core/restart/LevelReach.h"

#include <algorithm>
#include <map>

namespace mtc::core {

namespace {

enum class Flow { Next, Branch, Conditional, End };

Flow flowOf(JumpKind kind) {
    switch (kind) {
        case JumpKind::BRA:
            return Flow::Branch;
        case JumpKind::BEQ:
        case JumpKind::BNE:
        case JumpKind::BPL:
        case JumpKind::BMI:
        case JumpKind::BES:
        case JumpKind::BER:
        case JumpKind::BRF:
        case JumpKind::BSE:
        case JumpKind::BTE:
            return Flow::Conditional;
        case JumpKind::BSR:
        case JumpKind::BEV:
        case JumpKind::JSR:
        case JumpKind::JEV:
            return Flow::Next;  // the call returns to the next block
        case JumpKind::BST:
        case JumpKind::RET:
        case JumpKind::RTS:
        case JumpKind::JMP:
            return Flow::End;
    }
    return Flow::End;
}

/// Marks the blocks of next[0, n) not seen yet as seen: the first of them is
/// returned (to be walked at once), the others wait in `open`; -1 for none.
long markNew(const std::uint32_t* next, int n, std::vector<bool>& seen,
             std::vector<std::uint32_t>& open) {
    long first = -1;
    for (int i = 0; i < n; ++i) {
        if (seen[next[i]]) continue;
        seen[next[i]] = true;
        if (first < 0)
            first = next[i];
        else
            open.push_back(next[i]);
    }
    return first;
}

}  // namespace

int LevelReach::successors(std::uint32_t block, std::uint32_t next[2]) const {
    const Program& p = *program_;
    const Block b = p.blocks[block];
    if (b.flags & kBlockProgramEnd) return 0;
    const bool mayFallThrough = (b.flags & (kBlockSkip | kBlockHasError)) != 0;
    bool ends = false;
    Flow flow = Flow::Next;
    long label = -1;
    const std::size_t end =
        std::min<std::size_t>(std::size_t{b.firstWord} + b.wordCount, p.words.size());
    for (std::size_t w = b.firstWord; w < end; ++w) {
        // Only M and jump words change the flow: the others are not read whole.
        const WordKind kind = p.words.kindAt(w);
        if (kind != WordKind::M && kind != WordKind::Jump) continue;
        const Word word = p.words[w];
        if (word.kind == WordKind::M && word.expr < 0 && (word.number == 2 || word.number == 30))
            ends = true;  // M02 / M30 end the program before any jump
        if (word.kind != WordKind::Jump) continue;
        flow = flowOf(word.jump);
        if (flow == Flow::Branch || flow == Flow::Conditional)
            label = p.findLabel(p.text(word.text));  // -1: program 99 / cycles, off this program
    }
    int count = 0;
    const bool falls = mayFallThrough || (!ends && flow != Flow::Branch && flow != Flow::End);
    if (falls && block + 1 < p.blocks.size()) next[count++] = block + 1;
    if (!ends && label >= 0 && (flow == Flow::Branch || flow == Flow::Conditional))
        next[count++] = static_cast<std::uint32_t>(label);
    return count;
}

bool LevelReach::walk(const std::vector<std::uint32_t>& entries, std::vector<bool>& seen,
                      std::uint32_t stopAt) const {
    const std::size_t size = program_->blocks.size();
    seen.assign(size, false);
    std::vector<std::uint32_t> open;
    for (std::uint32_t e : entries)
        if (e < size && !seen[e]) {
            seen[e] = true;
            open.push_back(e);
        }
    while (!open.empty()) {
        long b = open.back();
        open.pop_back();
        // Straight on while the flow finds new blocks (the blocks seen are
        // the same in any order).
        while (b >= 0) {
            if (static_cast<std::uint32_t>(b) == stopAt) return true;
            std::uint32_t next[2];
            const int n = successors(static_cast<std::uint32_t>(b), next);
            b = markNew(next, n, seen, open);
        }
    }
    return false;
}

bool LevelReach::reaches(const std::vector<std::uint32_t>& entries, std::uint32_t block) const {
    if (block >= program_->blocks.size()) return false;
    std::vector<bool> seen;
    return walk(entries, seen, block);
}

std::vector<bool> LevelReach::reachable(const std::vector<std::uint32_t>& entries) const {
    std::vector<bool> seen;
    walk(entries, seen, ~std::uint32_t{0});
    return seen;
}

std::optional<LevelReach::Subroutine> LevelReach::subroutineOf(std::uint32_t block) const {
    const Program& p = *program_;
    std::map<long, std::uint32_t> calls;  // label block -> first calling block
    for (std::uint32_t b = 0; b < p.blocks.size(); ++b) {
        const Block blk = p.blocks[b];
        for (std::uint32_t w = blk.firstWord; w < blk.firstWord + blk.wordCount; ++w) {
            if (p.words.kindAt(w) != WordKind::Jump) continue;
            const Word word = p.words[w];
            if (word.jump != JumpKind::BSR && word.jump != JumpKind::BEV) continue;
            const long label = p.findLabel(p.text(word.text));
            if (label >= 0) calls.emplace(label, b);
        }
    }
    constexpr std::size_t kMaxLabelsTried = 64;  // a message, not a proof: bounded work
    std::size_t tried = 0;
    for (const auto& [label, call] : calls) {
        if (++tried > kMaxLabelsTried) break;
        if (!reaches({static_cast<std::uint32_t>(label)}, block)) continue;
        return Subroutine{std::string(p.text(p.blocks[static_cast<std::size_t>(label)].label)),
                          static_cast<std::uint32_t>(label), call};
    }
    return std::nullopt;
}

}  // namespace mtc::core
