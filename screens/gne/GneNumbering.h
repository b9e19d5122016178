#pragma once

// Block numbers of the lines the GNE writes back into an NC program (issue
// 15 §4, seed 001 ch. 1 and 10, decision GS-007): a line that stems from a
// program line keeps that line's block number (and its comment); a new line
// gets the enhanced number "N0053:0001" after the numbered line before it,
// as the compiler numbers the blocks it inserts. A program without block
// numbers gets none. Plain C++ (no Qt).

#include <map>
#include <string>
#include <vector>

namespace mtc::screens {

/// One line of the GNE's output and the program line it stems from.
struct GneOutputLine {
    std::string text;    ///< without block number ("LINE Z-20 X15", "G1 X10 Z-2")
    int sourceLine = 0;  ///< 1-based line of the program it replaces, 0 = new
};

/// Numbers output lines against the program's lines.
class GneNumbering {
  public:
    /// `programLines`: the whole program; `firstLine` .. `lastLine` the
    /// section being replaced (1-based; firstLine 0 = a new section that
    /// goes before line `insertLine`).
    GneNumbering(const std::vector<std::string>& programLines, int firstLine, int lastLine,
                 int insertLine);

    /// The output lines with their block numbers, joined by '\n'.
    std::string numbered(const std::vector<GneOutputLine>& lines);

  private:
    /// Block number, enhanced number and comment of a program line.
    struct Lead {
        bool numbered = false;
        int number = -1;
        int sub = 0;
        std::string prefix;   ///< "N0053 " / "/N0053:0002 " as written, with the blank
        std::string comment;  ///< ";..." outside quotes, "" if none
    };
    static Lead readLead(const std::string& line);
    bool fromSection(int line) const;
    int nextSub(int number);

    const std::vector<std::string>& lines_;
    int first_ = 0, last_ = 0;
    int before_ = -1;                ///< block number of the last numbered line before the section
    std::map<int, int> highestSub_;  ///< per block number, the highest enhanced number used
};

}  // namespace mtc::screens
