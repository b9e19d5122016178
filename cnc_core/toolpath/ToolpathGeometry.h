#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mtc::core {

/// What the toolpath view colours a move by.
enum class ToolpathKind : std::uint8_t {
    Rapid = 0,  ///< G0
    Feed = 1,   ///< G1 (straight feed move)
    Arc = 2,    ///< G2 / G3 (tessellated)
};
inline constexpr int kToolpathKinds = 3;
/// A path keeps at most this many distinct workpiece frames; a move in a
/// further one keeps the frame of the move before it (TP-019).
inline constexpr std::size_t kMaxToolpathFrames = 1024;

/// One programmed move as the view keeps it: where it came from and which
/// segments of the two layers draw it. The segments of move i are
/// [firstScene, moves[i+1].firstScene) and likewise for the developed layer.
struct ToolpathMove {
    int program = 0;
    std::uint32_t block = 0;  ///< index into Program::blocks
    std::uint32_t line = 0;   ///< 1-based source line
    ToolpathKind kind = ToolpathKind::Feed;
    std::uint8_t transformation = 30;  ///< 30, 31 or 32 (seed 003, ch. 4)
    std::uint16_t frame = 0;           ///< ToolpathGeometry::frames entry of its zero offset
    std::uint32_t firstScene = 0;
    std::uint32_t firstDeveloped = 0;
};

/// The workpiece frame of a move (TP-019): the zero offset in force (G53..G59)
/// and what it shifts each scene axis by (mm): workpiece coordinate = scene
/// coordinate - offset (0 for a scene axis no machine axis draws). The scene
/// axis of the machine axis with definition X reads diameters under G16
/// (TP-020): workpiece coordinate = 2 x (scene - offset) there.
struct ToolpathFrame {
    int code = 53;
    std::array<double, 3> offset{0, 0, 0};
    int radialAxis = -1;    ///< scene axis G15/G16 apply to (-1: none drawn)
    bool diameter = false;  ///< G16: radialAxis reads diameters

    /// Workpiece value (mm, diameter where it applies) of `scene` on scene axis `axis`.
    double workpiece(int axis, double scene) const {
        return (scene - offset[static_cast<std::size_t>(axis)]) * scale(axis);
    }
    /// The scene coordinate of workpiece value `value` on scene axis `axis`.
    double sceneOf(int axis, double value) const {
        return value / scale(axis) + offset[static_cast<std::size_t>(axis)];
    }
    /// Workpiece mm per scene mm on `axis`: 2 on a diameter axis, else 1.
    double scale(int axis) const { return diameter && axis == radialAxis ? 2.0 : 1.0; }

    bool operator==(const ToolpathFrame& other) const {
        return code == other.code && offset == other.offset && radialAxis == other.radialAxis &&
               diameter == other.diameter;
    }
    bool operator!=(const ToolpathFrame& other) const { return !(*this == other); }
};

/// Axis-aligned box of a layer (empty until a vertex is added).
struct ToolpathBounds {
    std::array<double, 3> min{0, 0, 0};
    std::array<double, 3> max{0, 0, 0};
    bool empty = true;

    /// Grows the box to contain (x, y, z).
    void add(double x, double y, double z);
    /// Largest edge of the box (0 when empty).
    double size() const;
};

/// Vertices and line segments of one picture. Segments follow each other
/// along chains: segment i runs from vertex segmentStart[i] to
/// segmentStart[i] + 1, so a continuous path stores each vertex once.
/// Vertices are float (the view's precision; 3 x 4 bytes each).
struct ToolpathLayer {
    std::vector<float> xyz;                   ///< 3 floats per vertex
    std::vector<std::uint32_t> segmentStart;  ///< first vertex of each segment
    ToolpathBounds bounds;

    std::size_t vertexCount() const { return xyz.size() / 3; }
    std::size_t segmentCount() const { return segmentStart.size(); }
    /// Vertex `index` as doubles.
    std::array<double, 3> vertex(std::size_t index) const;
    /// Appends a segment from the chain's last vertex to (x, y, z); starts a
    /// new chain at `from` when the last vertex is not (within 1e-6 mm) `from`.
    void addSegment(const std::array<double, 3>& from, const std::array<double, 3>& to);
    /// Forgets every vertex and segment.
    void clear();
    std::size_t memoryBytes() const;

  private:
    bool chainOpen_ = false;
};

/// The toolpath of a program run: moves in program order and two layers.
/// `scene` is the 3D picture in machine coordinates (mm) with G32 moves
/// wrapped onto the cylinder of radius RI; `developed` holds the G32 moves
/// only, in the developed plane (axial mm, circumferential mm, 0). Both
/// draw the path of the tool centre (with tool compensation, the cutter or
/// nose centre). Where compensation moves the tool off the programmed
/// contour, `contour` and `developedContour` hold the programmed contour of
/// those moves (same coordinates), so the view can show both.
struct ToolpathGeometry {
    std::vector<ToolpathMove> moves;
    /// The distinct workpiece frames of the moves (ToolpathMove::frame), at
    /// most kMaxToolpathFrames; empty until the first move.
    std::vector<ToolpathFrame> frames;
    ToolpathLayer scene;
    ToolpathLayer developed;
    ToolpathLayer contour;
    ToolpathLayer developedContour;
    double tolerance = 0.01;      ///< chordal tolerance the arcs were tessellated with (mm)
    double cylinderRadius = 0.0;  ///< RI of the last G32 move (0 = no G32 move)
    int cylinderAxis = -1;        ///< scene axis (0..2) of that cylinder's axis, -1 = none
    double cylinderFrom = 0.0;    ///< extent of the G32 moves along the cylinder axis
    double cylinderTo = 0.0;
    bool truncated = false;  ///< the segment limit cut the path short

    /// Segments of move `move` in the scene (developed) layer: [first, last).
    std::pair<std::uint32_t, std::uint32_t> sceneRange(std::size_t move) const;
    std::pair<std::uint32_t, std::uint32_t> developedRange(std::size_t move) const;
    /// Move that scene (developed) segment `segment` belongs to; -1 if none.
    long moveOfSceneSegment(std::uint32_t segment) const;
    long moveOfDevelopedSegment(std::uint32_t segment) const;
    /// Box of the feed and arc moves of the scene (developed) layer, without
    /// the rapids: what the view frames (empty when there is no such move).
    ToolpathBounds cuttingBounds(bool developed) const;
    /// Indices of the moves of block `block` of program `program` (in order).
    std::vector<std::uint32_t> movesOfBlock(int program, std::uint32_t block) const;
    /// The workpiece frame of move `move` (G53 without offset when out of range).
    ToolpathFrame frameOf(std::size_t move) const;
    /// Bytes held by the vectors (capacity).
    std::size_t memoryBytes() const;
    /// Empties everything (keeps the tolerance).
    void clear();
};

}  // namespace mtc::core
