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

/// The block holding word `index` (blocks hold consecutive words in order);
/// blocks.size() when none does.
std::uint32_t blockOfWord(const BlockList& blocks, std::uint32_t index) {
    std::size_t low = 0, high = blocks.size();  // first block with firstWord > index
    while (low < high) {
        const std::size_t mid = low + (high - low) / 2;
        if (blocks[mid].firstWord <= index)
            low = mid + 1;
        else
            high = mid;
    }
    if (low == 0) return static_cast<std::uint32_t>(blocks.size());
    const Block b = blocks[low - 1];
    return index < std::size_t{b.firstWord} + b.wordCount
               ? static_cast<std::uint32_t>(low - 1)
               : static_cast<std::uint32_t>(blocks.size());
}

}  // namespace

void LevelReach::BlockSet::setRange(std::size_t first, std::size_t last) {
    for (; first < last && first % 64; ++first)
        set(first);
    for (; first + 64 <= last; first += 64)
        bits_[first / 64] = ~std::uint64_t{0};
    for (; first < last; ++first)
        set(first);
}

std::size_t LevelReach::BlockSet::findSet(std::size_t first, std::size_t last) const {
    while (first < last) {
        const std::uint64_t word = bits_[first / 64] >> (first % 64);
        if (word) return std::min(last, first + static_cast<std::size_t>(__builtin_ctzll(word)));
        first = (first / 64 + 1) * 64;
    }
    return last;
}

LevelReach::LevelReach(ProgramPtr program) : program_(std::move(program)) {
    const Program& p = *program_;
    for (const std::uint32_t w : p.words.flowTurningWords()) {
        const std::uint32_t block = blockOfWord(p.blocks, w);
        if (block < p.blocks.size() && (turning_.empty() || turning_.back() != block))
            turning_.push_back(block);
    }
    // Words follow their blocks' order in a parsed program; kept sorted and
    // unique for any other (nextTurning searches it).
    std::sort(turning_.begin(), turning_.end());
    turning_.erase(std::unique(turning_.begin(), turning_.end()), turning_.end());
}

std::uint32_t LevelReach::nextTurning(std::uint32_t block) const {
    const auto it = std::lower_bound(turning_.begin(), turning_.end(), block);
    return it == turning_.end() ? static_cast<std::uint32_t>(program_->blocks.size()) : *it;
}

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
        if (endsProgram(word.kind, word.expr, word.number))
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

bool LevelReach::walk(const std::vector<std::uint32_t>& entries, BlockSet& seen,
                      std::uint32_t stopAt) const {
    const std::size_t size = program_->blocks.size();
    std::vector<std::uint32_t> open;
    for (std::uint32_t e : entries)
        if (e < size && !seen.test(e)) {
            seen.set(e);
            open.push_back(e);
        }
    while (!open.empty()) {
        std::uint32_t from = open.back();
        open.pop_back();
        for (;;) {
            // Straight on from `from` (seen) over the blocks that only go on
            // to the next, up to the next turning block or to a block seen
            // before (the blocks from there on are walked already or waiting
            // in `open`: the set is the same in any order).
            const std::uint32_t turn = nextTurning(from);
            const std::size_t last = std::min<std::size_t>(turn, size - 1);
            const std::size_t stop = seen.findSet(std::size_t{from} + 1, last + 1);
            seen.setRange(from, stop);
            if (stopAt >= from && stopAt < stop) return true;
            if (stop <= last || turn >= size) break;  // met a seen block, or ran off the end
            std::uint32_t next[2];
            const int n = successors(turn, next);
            long first = -1;
            for (int i = 0; i < n; ++i) {
                if (seen.test(next[i])) continue;
                seen.set(next[i]);
                if (first < 0)
                    first = next[i];
                else
                    open.push_back(next[i]);
            }
            if (first < 0) break;
            from = static_cast<std::uint32_t>(first);
        }
    }
    return false;
}

bool LevelReach::reaches(const std::vector<std::uint32_t>& entries, std::uint32_t block) const {
    if (block >= program_->blocks.size()) return false;
    BlockSet seen(program_->blocks.size());
    return walk(entries, seen, block);
}

LevelReach::BlockSet LevelReach::reachable(const std::vector<std::uint32_t>& entries) const {
    BlockSet seen(program_->blocks.size());
    walk(entries, seen, ~std::uint32_t{0});
    return seen;
}

std::optional<std::uint32_t> LevelReach::returnWithoutCall() const {
    // Blocks that are not turning blocks go on to the next one, and the
    // PROGRAMMENDE block ends the flow without an RTS.
    const Program& p = *program_;
    for (std::uint32_t b : turning_) {
        const Block blk = p.blocks[b];
        bool jumped = false;  // a second jump word is an error (JUMP_TWICE) and never runs
        for (std::uint32_t w = blk.firstWord; w < blk.firstWord + blk.wordCount; ++w) {
            const WordKind kind = p.words.kindAt(w);
            if (kind != WordKind::M && (kind != WordKind::Jump || jumped)) continue;
            const Word word = p.words[w];
            if (kind == WordKind::M) {
                if (endsProgram(word.kind, word.expr, word.number)) return std::nullopt;
                continue;
            }
            jumped = true;
            const Flow flow = flowOf(word.jump);
            if (flow == Flow::Branch || flow == Flow::End)
                return word.jump == JumpKind::RTS ? std::optional<std::uint32_t>(b) : std::nullopt;
        }
    }
    return std::nullopt;
}

std::optional<LevelReach::Subroutine> LevelReach::subroutineOf(std::uint32_t block) const {
    const Program& p = *program_;
    std::map<long, std::uint32_t> calls;  // label block -> first calling block
    for (std::uint32_t b : turning_) {    // every block with a jump word
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
