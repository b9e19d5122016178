#include "cnc_core/restart/ProgramScan.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <string>
#include <system_error>
#include <thread>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mtc::core {

namespace {

inline unsigned char fold(unsigned char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<unsigned char>(c | 0x20) : c;
}

bool equalFolded(const char* text, std::string_view needle) {
    for (std::size_t i = 0; i < needle.size(); ++i)
        if (fold(static_cast<unsigned char>(text[i])) !=
            fold(static_cast<unsigned char>(needle[i])))
            return false;
    return true;
}

/// How common a character is in NC text (0 = everywhere, 2 = rare): the
/// search anchors on the two rarest characters of the needle.
int rarity(unsigned char c) {
    if (c == ' ' || (c >= '0' && c <= '9')) return 0;
    switch (fold(c)) {
        case 'n':
        case 'g':
        case 'x':
        case 'y':
        case 'z':
        case 'f':
        case 'm':
        case 'i':
        case 'j':
        case 's':
        case 't':
        case '.':
        case '\n':
        case '\r':
            return 1;
        default:
            return 2;
    }
}

/// Two distinct positions of the needle to compare first: the rarest
/// characters, the second as far from the first as a tie allows (texts that
/// share the needle's start, "contour pass" for "contour passes", then
/// differ at the second anchor).
void pickAnchors(std::string_view needle, std::size_t& first, std::size_t& second) {
    first = 0;
    second = needle.size() - 1;
    int best = -1;
    for (std::size_t i = 0; i < needle.size(); ++i) {
        const int r = rarity(static_cast<unsigned char>(needle[i]));
        if (r > best) best = r, first = i;
    }
    best = -1;
    for (std::size_t i = 0; i < needle.size(); ++i) {
        if (i == first && needle.size() > 1) continue;
        const int r = rarity(static_cast<unsigned char>(needle[i]));
        if (r >= best) best = r, second = i;
    }
}

#if defined(__SSE2__)
/// One anchor character of the needle as a byte filter: (x | orMask) ==
/// value holds for every byte x that folds to the anchor (its two cases for
/// a letter), and for at most one other byte, which the full comparison
/// (equalFolded) then rejects. Two vector operations instead of folding the
/// text (five).
struct AnchorFilter {
    __m128i value;
    __m128i orMask;
};

AnchorFilter anchorFilter(char c) {
    const unsigned char folded = fold(static_cast<unsigned char>(c));
    const bool lowerCaseBit = (folded & 0x20) != 0;  // set for a-z: 'A' | 0x20 == 'a'
    return {_mm_set1_epi8(static_cast<char>(folded)),
            _mm_set1_epi8(static_cast<char>(lowerCaseBit ? 0x20 : 0))};
}

/// Bit i set when the needle may start at `start + i` (both anchors match).
inline unsigned candidates16(const char* start, std::size_t first, std::size_t second,
                             const AnchorFilter& a, const AnchorFilter& b) {
    const __m128i x =
        _mm_or_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(start + first)), a.orMask);
    const __m128i y =
        _mm_or_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(start + second)), b.orMask);
    return static_cast<unsigned>(
        _mm_movemask_epi8(_mm_and_si128(_mm_cmpeq_epi8(x, a.value), _mm_cmpeq_epi8(y, b.value))));
}
#endif

/// Last position < `before` where `needle` starts (case-insensitive), or npos.
std::size_t findFoldedBackward(std::string_view haystack, std::string_view needle,
                               std::size_t before) {
    if (needle.empty() || needle.size() > haystack.size()) return std::string_view::npos;
    std::size_t end = std::min(before, haystack.size() - needle.size() + 1);  // exclusive
    const char* text = haystack.data();
#if defined(__SSE2__)
    std::size_t first = 0, second = 0;
    pickAnchors(needle, first, second);
    const AnchorFilter a = anchorFilter(needle[first]);
    const AnchorFilter b = anchorFilter(needle[second]);
    while (end >= 16) {
        const std::size_t base = end - 16;
        unsigned mask = candidates16(text + base, first, second, a, b);
        while (mask) {
            const int bit = 31 - __builtin_clz(mask);
            if (equalFolded(text + base + bit, needle)) return base + static_cast<std::size_t>(bit);
            mask &= ~(1u << bit);
        }
        end = base;
    }
#endif
    while (end > 0) {
        --end;
        if (equalFolded(text + end, needle)) return end;
    }
    return std::string_view::npos;
}

}  // namespace

ProgramScan::ProgramScan(ProgramPtr program) : program_(std::move(program)) {}

std::size_t ProgramScan::findFolded(std::string_view haystack, std::string_view needle,
                                    std::size_t from) {
    if (needle.empty() || needle.size() > haystack.size()) return std::string_view::npos;
    const std::size_t lastStart = haystack.size() - needle.size();
    std::size_t pos = from;
    const char* text = haystack.data();
#if defined(__SSE2__)
    std::size_t first = 0, second = 0;
    pickAnchors(needle, first, second);
    const AnchorFilter a = anchorFilter(needle[first]);
    const AnchorFilter b = anchorFilter(needle[second]);
    // 32 bytes per step: two independent 16-byte filters keep the loads in
    // flight (four were no faster: the loop then waits for memory).
    for (; pos + 32 <= lastStart + 1; pos += 32) {
        std::uint32_t mask = candidates16(text + pos, first, second, a, b) |
                             candidates16(text + pos + 16, first, second, a, b) << 16;
        while (mask) {
            const int bit = __builtin_ctz(mask);
            if (equalFolded(text + pos + static_cast<std::size_t>(bit), needle))
                return pos + static_cast<std::size_t>(bit);
            mask &= mask - 1;
        }
    }
    for (; pos + 16 <= lastStart + 1; pos += 16) {
        unsigned mask = candidates16(text + pos, first, second, a, b);
        while (mask) {
            const int bit = __builtin_ctz(mask);
            if (equalFolded(text + pos + static_cast<std::size_t>(bit), needle))
                return pos + static_cast<std::size_t>(bit);
            mask &= mask - 1;
        }
    }
#endif
    for (; pos <= lastStart; ++pos)
        if (equalFolded(text + pos, needle)) return pos;
    return std::string_view::npos;
}

namespace {

/// First hit starting in [from, to) of `haystack`, searched in 1 MB pieces;
/// gives up (npos) between pieces once `stop` is set.
std::size_t findFoldedIn(std::string_view haystack, std::string_view needle, std::size_t from,
                         std::size_t to, const std::atomic<bool>& stop) {
    constexpr std::size_t kPiece = std::size_t{1} << 20;
    for (std::size_t piece = from; piece < to; piece += kPiece) {
        if (stop.load(std::memory_order_relaxed)) return std::string_view::npos;
        const std::size_t pieceEnd = std::min(to, piece + kPiece);
        // Starting points below pieceEnd: the text may run needle.size() - 1 further.
        const std::size_t textEnd = std::min(haystack.size(), pieceEnd + needle.size() - 1);
        const std::size_t hit = ProgramScan::findFolded(haystack.substr(0, textEnd), needle, piece);
        if (hit != std::string_view::npos) return hit;
    }
    return std::string_view::npos;
}

}  // namespace

std::size_t ProgramScan::findFoldedSplit(std::string_view haystack, std::string_view needle,
                                         std::size_t from, std::size_t splitBytes) {
    if (needle.empty() || needle.size() > haystack.size() || from >= haystack.size())
        return std::string_view::npos;
    const std::size_t starts = haystack.size() - needle.size() + 1;  // possible starting points
    if (from >= starts) return std::string_view::npos;
    if (starts - from < std::max<std::size_t>(splitBytes, 2))
        return findFolded(haystack, needle, from);
    const std::size_t middle = from + (starts - from) / 2;
    std::atomic<bool> firstHalfFound{false};
    std::size_t secondHit = std::string_view::npos;
    std::thread second;
    try {
        second = std::thread(
            [&] { secondHit = findFoldedIn(haystack, needle, middle, starts, firstHalfFound); });
    } catch (const std::system_error&) {
        return findFolded(haystack, needle, from);  // no thread to be had: one core then
    }
    const std::atomic<bool> never{false};
    const std::size_t firstHit = findFoldedIn(haystack, needle, from, middle, never);
    if (firstHit != std::string_view::npos) firstHalfFound = true;  // the second half may stop
    second.join();
    return firstHit != std::string_view::npos ? firstHit : secondHit;
}

std::uint32_t ProgramScan::lastSelectableBlock() const {
    const std::uint32_t count = blockCount();
    if (count == 0) return 0;
    if (count > 1 && (program_->blocks[count - 1].flags & kBlockProgramEnd)) return count - 2;
    return count - 1;
}

std::uint32_t ProgramScan::blockAtOffset(std::uint32_t offset) const {
    // First block whose text ends after `offset`.
    std::uint32_t low = 0, high = blockCount();
    while (low < high) {
        const std::uint32_t mid = low + (high - low) / 2;
        const TextSpan span = program_->blocks[mid].sourceText;
        if (span.offset + span.length <= offset)
            low = mid + 1;
        else
            high = mid;
    }
    return low;
}

std::uint32_t ProgramScan::blockAtLine(std::uint32_t line) const {
    // Last block starting on or before `line`.
    std::uint32_t low = 0, high = blockCount();
    while (low < high) {
        const std::uint32_t mid = low + (high - low) / 2;
        if (program_->blocks[mid].line <= line)
            low = mid + 1;
        else
            high = mid;
    }
    return low == 0 ? 0 : low - 1;
}

std::optional<std::uint32_t> ProgramScan::findTextAfter(std::uint32_t block,
                                                        std::string_view needle) const {
    const std::uint32_t count = blockCount();
    if (needle.empty() || block + 1 >= count) return std::nullopt;
    const TextSpan from = program_->blocks[block].sourceText;
    const TextSpan last = program_->blocks[lastSelectableBlock()].sourceText;
    const std::string_view source = program_->source;
    const std::size_t end = std::min<std::size_t>(source.size(), last.offset + last.length);
    const std::size_t start = from.offset + from.length;
    if (start >= end) return std::nullopt;
    const std::size_t hit = findFoldedSplit(source.substr(0, end), needle, start);
    if (hit == std::string_view::npos) return std::nullopt;
    const std::uint32_t found = blockAtOffset(static_cast<std::uint32_t>(hit));
    if (found >= count || found <= block) return std::nullopt;
    return std::min(found, lastSelectableBlock());
}

std::optional<std::uint32_t> ProgramScan::lastPrimaryIn(std::uint32_t first,
                                                        std::uint32_t end) const {
    if (!primariesBuilt_) {
        const std::uint32_t count = blockCount();
        for (std::uint32_t i = 0; i < count; ++i)
            if (program_->blocks[i].flags & kBlockPrimary) primaries_.push_back(i);
        primariesBuilt_ = true;
    }
    auto it = std::lower_bound(primaries_.begin(), primaries_.end(), end);
    if (it == primaries_.begin()) return std::nullopt;
    --it;
    if (*it < first) return std::nullopt;
    return *it;
}

long ProgramScan::jumpWordOf(std::uint32_t block) const {
    const Block b = program_->blocks[block];
    for (std::uint32_t w = b.firstWord; w < b.firstWord + b.wordCount; ++w)
        if (program_->words.kindAt(w) == WordKind::Jump) return static_cast<long>(w);
    return -1;
}

bool ProgramScan::hasG(std::uint32_t block, int g) const {
    const Block b = program_->blocks[block];
    for (std::uint32_t w = b.firstWord; w < b.firstWord + b.wordCount; ++w) {
        if (program_->words.kindAt(w) != WordKind::G) continue;
        const Word word = program_->words[w];
        if (word.expr < 0 && word.number == g) return true;
    }
    return false;
}

bool ProgramScan::modalActiveBefore(std::uint32_t block, int on, int off) const {
    // One backward pass for "G" + the common digits of both numbers (G9 for
    // G90/G91); each hit is read as a whole G number and checked against the
    // words of its block, so comments do not count.
    const std::string onText = std::to_string(on), offText = std::to_string(off);
    std::size_t common = 0;
    while (common < onText.size() && common < offText.size() && onText[common] == offText[common])
        ++common;
    const std::string needle = "G" + onText.substr(0, common);
    const std::string_view source = program_->source;
    std::size_t before = program_->blocks[block].sourceText.offset;
    while (true) {
        const std::size_t hit = findFoldedBackward(source, needle, before);
        if (hit == std::string_view::npos) return false;
        before = hit;
        long number = 0;
        std::size_t digit = hit + 1;
        for (; digit < source.size() && source[digit] >= '0' && source[digit] <= '9' &&
               digit < hit + 10;
             ++digit)
            number = number * 10 + (source[digit] - '0');
        if (digit == hit + 1 || (number != on && number != off)) continue;
        const std::uint32_t owner = blockAtOffset(static_cast<std::uint32_t>(hit));
        if (owner < blockCount() && hasG(owner, static_cast<int>(number))) return number == on;
    }
}

}  // namespace mtc::core
