#pragma once

/// Plane geometry of a disc (the cutter seen along its axis, or a turning
/// tool's nose) that moves along a straight chord: the region it sweeps is a
/// stadium. Both material models (HeightField, TurnedProfile) scan it line by
/// line, so the work per chord is the number of cells it covers, never the
/// length of a programmed number.
namespace mtc::core::removal {

/// A closed range [lo, hi]; empty when lo > hi (or a NaN is involved).
struct Span {
    double lo = 1.0;
    double hi = 0.0;
    bool empty() const { return !(lo <= hi); }
};

/// A disc of radius `radius` whose centre moves from (ax, ay) to (bx, by).
struct SweptDisc {
    double ax = 0.0, ay = 0.0;
    double bx = 0.0, by = 0.0;
    double radius = 0.0;
};

/// The x range of the swept region on the line y = `y` (empty when the line
/// misses it). The region is convex, so this is one range.
Span sweptRow(const SweptDisc& disc, double y);

/// sweptRow() for many rows of one chord: what does not depend on the row
/// is computed once (the models scan a chord row by row).
class SweptRowScanner {
  public:
    explicit SweptRowScanner(const SweptDisc& disc);
    Span row(double y) const;

  private:
    SweptDisc d_;
    double radiusSquared_;
    bool band_ = false;  ///< the chord has a length: a band joins the end discs
    double dx_ = 0.0, dy_ = 0.0, lengthSquared_ = 0.0, halfWidth_ = 0.0;
    double inverseDx_ = 0.0, inverseDy_ = 0.0;  ///< 0 for a zero component
};

/// The positions t in [0, 1] of the disc centre a + t (b - a) at which the
/// disc covers point (px, py): one range (empty when it never does).
Span coveringPositions(const SweptDisc& disc, double px, double py);

}  // namespace mtc::core::removal
