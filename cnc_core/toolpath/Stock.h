#pragma once

#include <array>
#include <string>
#include <vector>

namespace mtc::core {

/// The raw part the toolpath view draws around the path, in machine
/// coordinates (mm): a block or a cylinder along a scene axis. Given per
/// process in the machine configuration (`stock = ...`, docs/MACHINE-CONFIG.md).
struct Stock {
    enum class Shape { None, Block, Cylinder };
    Shape shape = Shape::None;
    std::array<double, 3> min{0, 0, 0};  ///< block: corners
    std::array<double, 3> max{0, 0, 0};
    int axis = 2;         ///< cylinder: scene axis of its axis (0 X, 1 Y, 2 Z)
    double radius = 0.0;  ///< cylinder radius
    double from = 0.0;    ///< cylinder: extent along its axis
    double to = 0.0;
    /// Cylinder: the blank inside the bar when it is not the whole bar (a
    /// GNE RAW contour, TP-021): a closed polygon in the plane through the
    /// axis, points (axial position, radius); the material at an axial
    /// position reaches out to the polygon's largest radius there. Empty:
    /// the whole bar.
    std::vector<std::array<double, 2>> outline;

    /// The axis-aligned box around the stock in scene coordinates (a
    /// cylinder's: its length along the axis, +-radius across); false and
    /// nothing written when there is no stock.
    bool box(std::array<double, 3>& low, std::array<double, 3>& high) const;
};

/// Reads "block XMIN XMAX YMIN YMAX ZMIN ZMAX" or "cylinder AXIS RADIUS FROM
/// TO" (AXIS = X, Y or Z); "none" or "" = no stock. False with a reason in
/// `error` for anything else (min > max, radius <= 0, ...).
bool parseStock(const std::string& text, Stock& stock, std::string& error);

struct ProcessConfig;
/// The stock of a process's configuration (none when it gives none).
Stock stockOf(const ProcessConfig& config);

}  // namespace mtc::core
