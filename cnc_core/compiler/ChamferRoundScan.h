#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cnc_core/compiler/CompilerPass.h"
#include "cnc_core/compiler/CornerGeometry.h"

namespace mtc::core {

/// Largest CF/RD value (mm): the NC's 5 + 4 digit range. Larger values are
/// refused (COMPILER_CFRD_VALUE) instead of being reduced step by step.
constexpr double kMaxCornerSize = 99999.9999;
/// Largest plane coordinate (mm) of a CF/RD motion block: beyond it a
/// double no longer holds the 0.0001 mm the corner is written with.
constexpr double kMaxCornerCoordinate = 1e9;

/// An axis or centre word of a block, with its place in the block text.
struct ScannedWord {
    std::string name;       ///< "X", "Z2", "I"
    double value = 0.0;     ///< programmed value (when !variable)
    bool variable = false;  ///< given by a variable or an expression
    std::size_t begin = 0;  ///< span in CompileBlock::text
    std::size_t end = 0;
};

/// The active plane as the compiler sees it: axis names and centre letters.
struct CompilerPlane {
    int code = 17;
    std::array<std::string, 2> axis = {"X", "Y"};  ///< 1st and 2nd plane axis
    std::array<char, 2> centre = {'I', 'J'};       ///< centre letters of the two axes
};

/// Indices [begin, end) of a block's words in a ScanResult word pool.
struct WordRange {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    std::size_t size() const { return end - begin; }
    bool empty() const { return end == begin; }
};

/// What the CF/RD pass needs to know of one block of the sequence. The
/// problem texts are static strings (nullptr = no problem).
struct ScannedBlock {
    bool motion = false;            ///< has axis words (not a G20 plane definition)
    int motionG = 0;                ///< active G0..G3 for this block
    bool explicitMotionG = false;   ///< the block writes its G0..G3
    bool absolute = true;           ///< G90
    bool diameter = false;          ///< G16 (X values are diameters)
    std::uint32_t plane = 0;        ///< plane active for this block (ScanResult::planes)
    const char* illegal = nullptr;  ///< first function that forbids CF/RD across it
    bool illegalIsG = false;        ///< `illegal` is a G function (illegalG says which)
    int illegalG = -1;              ///< its number (-1: a computed G function)
    bool outOfPlane = false;        ///< moves an axis outside the plane
    bool planeVariable = false;     ///< plane end point / centre given by a variable
    bool startKnown = false;        ///< start point in the plane known
    PathElement element;            ///< the plane motion (if motion && valid)
    bool validElement = false;
    const char* elementProblem = nullptr;  ///< why not (radius mismatch, zero length)
    WordRange axes;                        ///< axis words in ScanResult::axisWords
    WordRange centres;                     ///< I J K words in ScanResult::centreWords
    // CF / RD instruction of the block
    int cornerCount = 0;  ///< CF/RD words in the block
    CornerKind kind = CornerKind::Chamfer;
    double size = 0.0;
    const char* sizeProblem = nullptr;           ///< nullptr = constant value
    std::size_t cornerBegin = 0, cornerEnd = 0;  ///< span of the CF/RD word
};

/// The scanned blocks (one per sequence block), the pools of their words
/// and the planes they use (a new entry only where a block changes the plane).
struct ScanResult {
    std::vector<ScannedBlock> blocks;
    std::vector<ScannedWord> axisWords;
    std::vector<ScannedWord> centreWords;
    std::vector<CompilerPlane> planes;

    const CompilerPlane& planeOf(const ScannedBlock& block) const { return planes[block.plane]; }
};

/// `a == b` for the short axis names ("X", "Z2"), compared inline.
inline bool sameAxisName(const std::string& a, const std::string& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i] != b[i]) return false;
    return true;
}

/// "a change of plane (G18)": the illegal function of `block` ("" = none).
std::string describeIllegal(const ScannedBlock& block);

/// Scans every block of the sequence in program order, tracking the modal
/// state the geometry needs (G0-G3, plane G17-G20, G90/G91, G15/G16, the
/// positions of the plane axes). `initialPlane` is the process's default.
ScanResult scanBlocks(const BlockSequence& blocks, const ParsedSequence& parsed,
                      const CompilerOptions& options);

/// The scale from programmed to geometric units of axis `name` (0.5 for the
/// X axis under diameter programming).
inline double axisScale(const std::string& name, bool diameter) {
    return diameter && !name.empty() && name[0] == 'X' ? 0.5 : 1.0;
}

}  // namespace mtc::core
