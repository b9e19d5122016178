#include "cnc_core/language/Keywords.h"

#include <algorithm>
#include <array>

namespace mtc::core {

namespace {

struct Entry {
    std::string_view name;
    KeywordClass keywordClass;
    JumpKind jump;
};

constexpr JumpKind kNoJump = JumpKind::BRA;

// Order of JumpKind.
constexpr std::string_view kJumpNames[] = {"BRA", "BEQ", "BNE", "BPL", "BMI", "BST",
                                           "RET", "BSR", "RTS", "JSR", "JMP", "BES",
                                           "BER", "BEV", "JEV", "BRF", "BSE", "BTE"};

constexpr Entry kEntries[] = {
    {"RI", KeywordClass::EffectiveRadius, kNoJump},
    {"MTD", KeywordClass::Mtd, kNoJump},
    {"SPC", KeywordClass::ReadOnly, kNoJump},
    {"TIME", KeywordClass::ReadOnly, kNoJump},
    {"PROGRAMMENDE", KeywordClass::ProgramEnd, kNoJump},
    // Tool storage and tool transfer (seed 000, 5.4).
    {"MTP", KeywordClass::Command, kNoJump},
    {"MMP", KeywordClass::Command, kNoJump},
    {"MFP", KeywordClass::Command, kNoJump},
    {"MHP", KeywordClass::Command, kNoJump},
    {"MOP", KeywordClass::Command, kNoJump},
    {"MRF", KeywordClass::Command, kNoJump},
    {"MRY", KeywordClass::Command, kNoJump},
    {"MRV", KeywordClass::Command, kNoJump},
    {"TCH", KeywordClass::Command, kNoJump},
    {"TMS", KeywordClass::Command, kNoJump},
    {"TSM", KeywordClass::Command, kNoJump},
    {"TSE", KeywordClass::Command, kNoJump},
    {"TPE", KeywordClass::Command, kNoJump},
    {"TLD", KeywordClass::Command, kNoJump},
    // Position reading, axis transfer, drive data (seed 000, 5.4).
    {"PMP", KeywordClass::Command, kNoJump},
    {"NMP", KeywordClass::Command, kNoJump},
    {"GAX", KeywordClass::Command, kNoJump},
    {"FAX", KeywordClass::Command, kNoJump},
    {"AXD", KeywordClass::Command, kNoJump},
    {"ITM", KeywordClass::Command, kNoJump},  // idle thrust measurement (seed 002, 3)
    {"ACC", KeywordClass::Command, kNoJump},
    // Process control and synchronisation (seed 000, 5.4), events (seed 001, 6).
    {"DP", KeywordClass::Command, kNoJump},
    {"SP", KeywordClass::Command, kNoJump},
    {"RP", KeywordClass::Command, kNoJump},
    {"AP", KeywordClass::Command, kNoJump},
    {"WP", KeywordClass::Command, kNoJump},
    {"LP", KeywordClass::Command, kNoJump},
    {"POK", KeywordClass::Command, kNoJump},
    {"WES", KeywordClass::Command, kNoJump},
    {"WER", KeywordClass::Command, kNoJump},
    {"SE", KeywordClass::Command, kNoJump},
    {"RE", KeywordClass::Command, kNoJump},
    {"BRJ", KeywordClass::Command, kNoJump},
    // NC compiler keywords (seed 001, ch. 2-6 and 12).
    {"CF", KeywordClass::CompilerCommand, kNoJump},
    {"RD", KeywordClass::CompilerCommand, kNoJump},
    {"MODF_ON", KeywordClass::CompilerCommand, kNoJump},
    {"MODF_OFF", KeywordClass::CompilerCommand, kNoJump},
    {"LA_ON", KeywordClass::CompilerCommand, kNoJump},
    {"LA_OFF", KeywordClass::CompilerCommand, kNoJump},
    {"METB", KeywordClass::CompilerCommand, kNoJump},
    {"VFBT", KeywordClass::CompilerCommand, kNoJump},
    {"BBTRC", KeywordClass::CompilerCommand, kNoJump},
    {"TL_RADIUS", KeywordClass::CompilerCommand, kNoJump},
    {"TRC", KeywordClass::CompilerCommand, kNoJump},
    {"ADTRC", KeywordClass::CompilerCommand, kNoJump},
    {"ACD", KeywordClass::CompilerCommand, kNoJump},
    {"ACD_COMP", KeywordClass::CompilerCommand, kNoJump},
    {"ACC_EFF", KeywordClass::CompilerCommand, kNoJump},
    {"CONT", KeywordClass::CompilerCommand, kNoJump},
    {"END_CONT", KeywordClass::CompilerCommand, kNoJump},
    {"CYCLE_MP", KeywordClass::CompilerCommand, kNoJump},
    {"DEFINE", KeywordClass::CompilerRestOfBlock, kNoJump},
    {"START", KeywordClass::CompilerRestOfBlock, kNoJump},
    {"LINE", KeywordClass::CompilerRestOfBlock, kNoJump},
    {"CW", KeywordClass::CompilerRestOfBlock, kNoJump},
    {"CCW", KeywordClass::CompilerRestOfBlock, kNoJump},
    {"RELIEF", KeywordClass::CompilerRestOfBlock, kNoJump},
};

bool hasNumberedPrefix(std::string_view name, std::string_view prefix) {
    if (name.size() <= prefix.size() || name.substr(0, prefix.size()) != prefix) return false;
    for (char c : name.substr(prefix.size()))
        if (c < '0' || c > '9') return false;
    return true;
}

constexpr std::size_t kJumpCount = sizeof kJumpNames / sizeof kJumpNames[0];
constexpr std::size_t kEntryCount = sizeof kEntries / sizeof kEntries[0];
using KeywordTable = std::array<Entry, kJumpCount + kEntryCount>;

/// Jump names and kEntries in one table sorted by name, built at compile
/// time (insertion sort: stable, so for a name listed twice the first entry
/// wins, as in a linear scan).
constexpr KeywordTable sortedKeywords() {
    KeywordTable table{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < kJumpCount; ++i)
        table[n++] = Entry{kJumpNames[i], KeywordClass::Jump, static_cast<JumpKind>(i)};
    for (std::size_t i = 0; i < kEntryCount; ++i)
        table[n++] = kEntries[i];
    for (std::size_t i = 1; i < n; ++i)
        for (std::size_t k = i; k > 0 && table[k].name < table[k - 1].name; --k) {
            const Entry swap = table[k];
            table[k] = table[k - 1];
            table[k - 1] = swap;
        }
    return table;
}

constexpr KeywordTable kSortedKeywords = sortedKeywords();

}  // namespace

KeywordInfo lookupKeyword(std::string_view name) {
    const auto it =
        std::lower_bound(kSortedKeywords.begin(), kSortedKeywords.end(), name,
                         [](const Entry& entry, std::string_view key) { return entry.name < key; });
    if (it != kSortedKeywords.end() && it->name == name) return {it->keywordClass, it->jump};
    if (hasNumberedPrefix(name, "FORM_") || hasNumberedPrefix(name, "CYCLE_") ||
        hasNumberedPrefix(name, "WINDOW_"))
        return {KeywordClass::CompilerCommand, kNoJump};
    if (name.size() == 2 && name[0] == 'F' && isAxisLetter(name[1]))
        return {KeywordClass::AxisFeed, kNoJump};
    return {};
}

std::string_view jumpName(JumpKind kind) {
    auto index = static_cast<std::size_t>(kind);
    return index < sizeof kJumpNames / sizeof kJumpNames[0] ? kJumpNames[index] : "?";
}

}  // namespace mtc::core
