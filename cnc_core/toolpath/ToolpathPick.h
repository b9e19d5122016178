#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "cnc_core/toolpath/ToolpathDecimation.h"
#include "cnc_core/toolpath/ToolpathGeometry.h"

namespace mtc::core {

/// How the view maps layer coordinates onto its pixels: a row-major 4x4
/// matrix from (x, y, z, 1) to normalised device coordinates (-1..1), and
/// the pixel rectangle of the viewport (origin bottom left).
struct ScreenProjection {
    std::array<double, 16> toNdc{};
    double originX = 0.0, originY = 0.0, width = 1.0, height = 1.0;

    /// Pixel position (x, y) of a layer point.
    std::array<double, 2> pixel(const float* xyz) const;
};

/// The segment of `layer` nearest on the screen to pixel (x, y), if one is
/// within `maxPixels`. With a coarse copy (`coarse` has cells) only the
/// full segments of cells that can hold the nearest one are measured: a
/// full segment lies within the cell's tolerance of its cell, so cells
/// farther than the best segment found plus that tolerance are skipped.
/// Without one (or when it left runs out) every segment is measured.
std::optional<std::uint32_t> pickSegment(const ToolpathLayer& layer, const DecimatedLayer& coarse,
                                         const ScreenProjection& view, double x, double y,
                                         double maxPixels);

}  // namespace mtc::core
