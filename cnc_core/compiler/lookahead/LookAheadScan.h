#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cnc_core/compiler/lookahead/LookAheadAnalysis.h"

/// Internal pieces of the look-ahead analysis shared by its source files.
namespace mtc::core::lookahead::detail {

/// Words of one block as written: the text before the first word (label),
/// each word's raw text and the ';' comment.
struct BlockWords {
    std::string lead;
    std::vector<std::string> raw;
    std::string comment;
};

/// The keyword at the start of a command word's text ("METB" of "METB=5").
inline std::string keywordIn(std::string_view text) {
    std::size_t end = 0;
    while (end < text.size() && ((text[end] >= 'A' && text[end] <= 'Z') ||
                                 (text[end] >= '0' && text[end] <= '9') || text[end] == '_'))
        ++end;
    return std::string(text.substr(0, end));
}

/// Value text after '=' of an assignment ("=5" -> "5"); "" when there is no '='.
inline std::string_view valueAfterEquals(std::string_view args) {
    const std::size_t eq = args.find('=');
    return eq == std::string_view::npos ? std::string_view() : args.substr(eq + 1);
}

/// Splits the text of `block` (parsed as `parsed`) into its words.
BlockWords splitWords(const CompileBlock& block, const Program& program, const Block& parsed);

/// Joins lead, words and comment into one block text.
std::string joinWords(const std::string& lead, const std::vector<std::string>& words,
                      const std::string& comment);

/// Modal state of the source program the scan follows, block by block.
struct ScanState {
    AxisVector position;
    std::vector<bool> known;  ///< position of each axis known
    int motion = 0;           ///< 0..3
    int plane = 17;           ///< 17, 18, 19, 20
    bool incremental = false;
    double pathFeed = 0.0;  ///< last F, mm/min (0 = none)
    int axisFeedAxis = -1;  ///< axis of the last F<axis>= while it is the last velocity
    double axisFeedValue = 0.0;
    double accEff = 100.0;
    double metbMs = 5.0, vfbt = 1.0, adtrc = 0.0;
    int bbtrc = 3, trc = 0;
    long tool = 0, edge = 1;
    std::map<std::pair<long, long>, double> radii;  ///< TL_RADIUS[T, E]
};

/// Axis definitions (X Y Z) to axis indices of the table: plane axes.
struct PlaneAxes {
    int first = -1, second = -1;
};

/// The two plane axes of G17/G18/G19 in `limits` (by the axis names'
/// base definitions `definitions`: one letter per axis).
PlaneAxes planeAxes(int plane, const std::vector<char>& definitions);

/// Scans a block sequence for look-ahead variables and segments
/// (LookAheadAnalysis.cpp: variables and modal state; LookAheadSegmentScan.cpp:
/// the rules inside a segment and its planning).
class Analyzer {
  public:
    Analyzer(const BlockSequence& blocks, CompileContext& context,
             const LookAheadDefaults& defaults);
    /// Scans every block; reports through the context.
    LookAheadAnalysis run();

  private:
    struct Range {
        const char* name;
        double min, max;
        bool whole;
    };

    char definitionOf(int axis) const;
    bool report(std::size_t block, std::string code, std::string message,
                std::vector<std::string> details = {});
    void scanBlock(std::size_t i, const Program& program, const Block& block);
    void outsideBlock(std::size_t i, const Program& program, const Block& block,
                      std::vector<bool>& drop);
    void modalWord(const Word& w, AxisVector& target);
    int axisIndex(const Word& w) const;
    bool compilerWordOutside(std::size_t i, const Program& program, const Word& w);
    std::optional<double> rangedValue(std::size_t i, const Range& range, std::string_view args);
    CompileTimeValue evaluate(std::size_t i, std::string_view text);
    bool variableWord(std::size_t i, const std::string& keyword, std::string_view args);
    void toolRadius(std::size_t i, std::string_view args);

    bool startSegment(std::size_t i);
    void insideBlock(std::size_t i, const Program& program, const Block& block,
                     const BlockWords& words, std::vector<bool>& drop);
    bool insideWord(std::size_t i, const Program& program, const Word& w, AxisVector& target,
                    AxisVector& center, unsigned& centerMask, int& motion);
    void addElement(std::size_t i, int motion, const AxisVector& target, const AxisVector& center,
                    unsigned centerMask, const BlockWords& words, const std::vector<bool>& drop);
    bool arcCenter(std::size_t i, const AxisVector& target, AxisVector& center, unsigned centerMask,
                   PlaneAxes plane);
    void finishSegment(std::size_t i);
    void planSegment();
    std::optional<double> toolRadiusForTrc(std::size_t i);

    const BlockSequence& blocks_;
    CompileContext& context_;
    const LookAheadDefaults& defaults_;
    AxisLimits limits_;
    std::vector<char> definitions_;
    double blockCycleMs_ = 2.0;
    int processIndex_ = 0;
    ScanState state_;
    bool inside_ = false;
    std::size_t motionBlock_ = static_cast<std::size_t>(-1);  ///< block that became an element
    LookAheadSegment segment_;
    LookAheadAnalysis result_;
};

}  // namespace mtc::core::lookahead::detail
