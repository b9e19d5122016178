#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "cnc_core/compiler/CompilerPass.h"

namespace mtc::core {

/// Macro technique (seed 001, ch. 4): `DEFINE name AS instructions` defines
/// a local macro valid in the following blocks; global macros come from the
/// NC options. Every later use of a macro name (as a whole word, outside
/// comments, labels and free texts) is replaced by its instructions. The
/// DEFINE block stays as an empty block (label and comment kept).
class MacroPass : public CompilerPass {
  public:
    std::string_view name() const override { return "macros"; }
    int order() const override { return 100; }
    std::vector<std::string> keywords() const override { return {"DEFINE"}; }
    void run(BlockSequence& blocks, CompileContext& context) const override;
};

using MacroTable = std::unordered_map<std::string, std::string>;

/// The names of a macro table prepared for many block texts: a filter on
/// first letters and lengths, then (for a few macros) a plain comparison
/// instead of hashing a copy of the name. Refers to `table`: build it anew
/// after every change of the table.
class MacroMatcher {
  public:
    explicit MacroMatcher(const MacroTable& table);
    /// The instructions of the macro called `name` (a name starting with
    /// A-Z), or nullptr. Inline: the compiler asks for every name of every
    /// block, and the filter refuses nearly all of them.
    const std::string* find(std::string_view name) const {
        if (name.size() < shortest_ || name.size() > longest_ ||
            !((firstLetters_ >> (name[0] - 'A')) & 1u))
            return nullptr;
        if (entries_.empty()) return findInTable(name);
        for (const auto& [entryName, body] : entries_)
            if (entryName == name) return body;
        return nullptr;
    }
    /// False when no name can ever match (no table entry starts with A-Z).
    bool canMatch() const { return firstLetters_ != 0; }
    /// Bit c - 'A' set: some macro name starts with the letter c.
    std::uint32_t firstLetters() const { return firstLetters_; }

  private:
    static constexpr std::size_t kCompared = 8;  ///< up to this many: compared one by one

    const std::string* findInTable(std::string_view name) const;

    const MacroTable& table_;
    std::uint32_t firstLetters_ = 0;  ///< bit c - 'A': some name starts with c
    std::size_t shortest_ = std::string::npos, longest_ = 0;
    std::vector<std::pair<std::string_view, const std::string*>> entries_;  ///< when few
};

/// Replaces every macro name of `table` in `text` (whole words outside the
/// comment, labels, variables and free texts) and puts the result in `out`.
/// Returns false (and leaves `out` alone) when no macro is used. Also the
/// function for global macros in an MDI line.
bool expandMacros(const std::string& text, const MacroTable& table, std::string& out);
/// The same with a prepared table (the compiler's loop over the blocks;
/// `out` may be `text`).
bool expandMacros(const std::string& text, const MacroMatcher& macros, std::string& out);
/// First macro name of `table` used in `text`, or "" (for the nesting check).
std::string findMacroUse(std::string_view text, const MacroTable& table);
/// Problem with a macro name ("" when the name is fine): length (<= 20),
/// characters, keyword.
std::string checkMacroName(std::string_view name);

}  // namespace mtc::core
