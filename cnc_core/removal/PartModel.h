#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "cnc_core/removal/DevelopedSurface.h"
#include "cnc_core/removal/HeightField.h"
#include "cnc_core/removal/TurnedProfile.h"
#include "cnc_core/toolpath/Stock.h"

namespace mtc::core::removal {

/// Finest and coarsest resolution (mm) a simulation accepts.
inline constexpr double kMinResolution = 0.01;
inline constexpr double kMaxResolution = 10.0;
/// Most cells of a part: height field cells, or slices x angular segments of
/// a turned part. Memory (4 bytes a cell) and the STL (about 100 bytes a
/// cell) stay bounded whatever the stock and resolution (D-020).
inline constexpr std::uint64_t kMaxRemovalCells = 2'000'000;

/// How finely the part is simulated.
struct RemovalSettings {
    double resolution = 0.2;  ///< largest cell edge (mm)
    std::uint64_t maxCells = kMaxRemovalCells;
};

/// Most cells of the part the panel shows (the finished part, the part cut
/// live): its mesh, about two triangles a cell, stays near 10 MB and quick
/// to draw on llvmpipe (TP-023).
inline constexpr std::uint64_t kViewCells = 250'000;

/// The finest of 0.2, 0.3, 0.5, 1, 2, 5 and 10 mm at which `stock` needs at
/// most `maxCells` cells (PartModel::create() counts them, as for the real
/// run); 10 mm when none fits (create() then refuses the stock).
RemovalSettings fittingSettings(const Stock& stock, bool turning, std::uint64_t maxCells);

/// Why `resolution` cannot be used ("" when it can): NaN, infinite, outside
/// kMinResolution .. kMaxResolution.
std::string resolutionProblem(double resolution);

/// The raw part being cut: a block becomes a HeightField (mill), a cylinder a
/// TurnedProfile around its axis (lathe). Positions are scene coordinates
/// (machine X, Y, Z in mm, as the toolpath view draws them).
class PartModel {
  public:
    /// The model of `stock` at `settings`: a block on a milling process, a
    /// cylinder on a turning process (`turning`: default plane G18, the
    /// lathe's). Nullopt with `error` when there is no stock, the other
    /// combinations (a z-map along Z cannot hold a bar on a mill, a turned
    /// profile not a block on a lathe), the resolution is refused or the
    /// part would need more than settings.maxCells cells (the message gives
    /// the coarsest resolution that fits).
    static std::optional<PartModel> create(const Stock& stock, const RemovalSettings& settings,
                                           bool turning, std::string& error);

    /// Sweeps the tool from scene point `a` to `b`: the face centre of a
    /// flat end mill of tool.radius (along Z), or on the lathe the nose
    /// centre / tip centre of `tool` (TurnedProfile::cut). True when
    /// material was removed.
    bool cut(const std::array<double, 3>& a, const std::array<double, 3>& b, const Cutter& tool);

    /// The same sweep as cut() asked without cutting: does the tool come
    /// below the material's surface + `margin` anywhere (HeightField::touches,
    /// TurnedProfile::touches)? The part does not change.
    bool touches(const std::array<double, 3>& a, const std::array<double, 3>& b, const Cutter& tool,
                 double margin) const;

    /// The turned part's jacket for G32 cuts (D-027), made at the first
    /// call (nullptr with `note` on a height field): angular columns of at
    /// most the resolution on the bar x the profile's slices, or fewer
    /// columns (at least angularSegments()) when that would exceed the
    /// settings' maxCells — then `note` says how many and how wide. `note`
    /// is empty otherwise, and on every later call.
    const DevelopedSurface* makeJacket(std::string& note);
    /// Sweeps a radial end mill of `toolRadius` over the jacket (made by
    /// makeJacket() first; false without it). True when material was removed.
    bool cutJacket(const JacketPoint& a, const JacketPoint& b, double toolRadius);
    /// The same sweep as cutJacket() asked without cutting
    /// (DevelopedSurface::touches); false without a jacket.
    bool touchesJacket(const JacketPoint& a, const JacketPoint& b, double toolRadius,
                       double margin) const;
    const DevelopedSurface* jacket() const { return jacket_ ? &*jacket_ : nullptr; }
    /// Material the G32 cuts took away below the turned profile (mm^3; 0
    /// without a jacket); part of removedVolume().
    double developedVolume() const;

    /// Material taken away so far (mm^3), the G32 cuts included.
    double removedVolume() const;
    /// The blank's volume before any cut (mm^3): the block, or the turned
    /// profile's (the bar, or a RAW contour's preform, TP-021).
    double blankVolume() const;
    double resolution() const { return resolution_; }
    /// Cells the model has (height field cells or slices x segments).
    std::uint64_t cells() const;

    const HeightField* heightField() const { return field_ ? &*field_ : nullptr; }
    const TurnedProfile* profile() const { return profile_ ? &*profile_ : nullptr; }
    /// Turned part: scene axis of the spindle axis and of the radius.
    int axialAxis() const { return axial_; }
    int radialAxis() const { return radial_; }
    /// Turned part: facets around the axis of its revolved surface.
    int angularSegments() const { return segments_; }

  private:
    PartModel() = default;

    double resolution_ = 0.2;
    std::uint64_t maxCells_ = kMaxRemovalCells;
    std::optional<HeightField> field_;
    std::optional<DevelopedSurface> jacket_;
    std::optional<TurnedProfile> profile_;
    int axial_ = 2;
    int radial_ = 0;
    int segments_ = 0;
};

}  // namespace mtc::core::removal
