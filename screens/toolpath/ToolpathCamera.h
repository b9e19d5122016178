#pragma once

#include <array>

namespace mtc::screens {

/// The view presets of the toolpath view: the plane views of G17 (XY, seen
/// from +Z), G18 (ZX, Z to the right, X up), G19 (YZ, seen from +X) and an
/// isometric view.
enum class ToolpathPreset { G17, G18, G19, Isometric };

/// Orientation of an orthographic camera: the direction it looks along and
/// the screen's up direction (unit vectors, perpendicular).
struct CameraPose {
    std::array<double, 3> direction{0, 0, -1};
    std::array<double, 3> up{0, 1, 0};

    /// Screen right = direction x up.
    std::array<double, 3> right() const;
    /// Turns the pose by `azimuth` degrees about the screen's up and
    /// `elevation` degrees about the screen's right (the view orbits).
    void rotate(double azimuth, double elevation);
};

/// The pose of a preset.
CameraPose presetPose(ToolpathPreset preset);
/// "G17 (XY)", "G18 (ZX)", "G19 (YZ)", "isometric".
const char* presetName(ToolpathPreset preset);

}  // namespace mtc::screens
