#include "cnc_core/removal/PartModel.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <locale>
#include <sstream>

#include "cnc_core/toolpath/CurveMath.h"

namespace mtc::core::removal {

namespace {

constexpr int kMinSegments = 24;
constexpr int kMaxSegments = 720;

std::string millimetres(double value) {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out << value;
    return out.str();
}

/// Cells needed along an extent (at least one), as a double: never overflows.
double cellsAlong(double extent, double resolution) {
    return std::max(1.0, std::ceil(extent / resolution - 1e-9));
}

std::string tooManyCells(double cells, const RemovalSettings& settings, double area) {
    // Cells grow with 1 / resolution^2 (height field) or about that (turned):
    // the resolution that brings the count under the cap.
    const double coarsest = std::sqrt(area / static_cast<double>(settings.maxCells));
    std::ostringstream count;
    count.imbue(std::locale::classic());
    count << std::fixed << std::setprecision(0) << cells;
    return "resolution " + millimetres(settings.resolution) + " mm needs " + count.str() +
           " cells for this stock; at most " + std::to_string(settings.maxCells) +
           " are simulated (try " + millimetres(std::ceil(coarsest * 1000.0) / 1000.0) +
           " mm or coarser)";
}

/// The stock's volume in mm^3 (0 without a stock): the most a program can
/// remove. Infinite for a stock whose extents overflow it (1e308 mm).
double stockVolume(const Stock& stock) {
    if (stock.shape == Stock::Shape::Block)
        return (stock.max[0] - stock.min[0]) * (stock.max[1] - stock.min[1]) *
               (stock.max[2] - stock.min[2]);
    if (stock.shape == Stock::Shape::Cylinder)
        return curve::kPi * stock.radius * stock.radius * (stock.to - stock.from);
    return 0.0;
}

}  // namespace

std::string resolutionProblem(double resolution) {
    if (!std::isfinite(resolution) || !(resolution >= kMinResolution) ||
        !(resolution <= kMaxResolution))
        return "resolution must be a number of millimetres from " + millimetres(kMinResolution) +
               " to " + millimetres(kMaxResolution);
    return {};
}

std::optional<PartModel> PartModel::create(const Stock& stock, const RemovalSettings& settings,
                                           bool turning, std::string& error) {
    error = resolutionProblem(settings.resolution);
    if (!error.empty()) return std::nullopt;
    if (stock.shape == Stock::Shape::Block && turning) {
        error =
            "a block stock on a turning process (default plane G18) is not simulated: the "
            "turned profile needs a cylinder (stock = cylinder ...)";
        return std::nullopt;
    }
    if (stock.shape == Stock::Shape::Cylinder && !turning) {
        error =
            "a cylinder stock on a milling process is not simulated: the height field needs "
            "a block (stock = block ...)";
        return std::nullopt;
    }
    if (!std::isfinite(stockVolume(stock))) {
        // The removed volume is the stock's less what is left: it would be
        // inf - inf (fuzz finding reentry 5a25b86: a bar of radius 1.8e308).
        error = "the stock is too large to simulate: its volume exceeds every number";
        return std::nullopt;
    }
    const double res = settings.resolution;
    PartModel model;
    model.resolution_ = res;
    model.maxCells_ = settings.maxCells;
    if (stock.shape == Stock::Shape::Block) {
        const double columns = cellsAlong(stock.max[0] - stock.min[0], res);
        const double rows = cellsAlong(stock.max[1] - stock.min[1], res);
        if (columns * rows > static_cast<double>(settings.maxCells)) {
            const double area = (stock.max[0] - stock.min[0]) * (stock.max[1] - stock.min[1]);
            error = tooManyCells(columns * rows, settings, area);
            return std::nullopt;
        }
        model.field_.emplace(Box{stock.min, stock.max}, static_cast<int>(columns),
                             static_cast<int>(rows));
        return model;
    }
    if (stock.shape == Stock::Shape::Cylinder) {
        const double circumference = 2.0 * curve::kPi * stock.radius;
        const int segments = std::clamp(curve::arcChords(stock.radius, 2.0 * curve::kPi, res / 4.0),
                                        kMinSegments, kMaxSegments);
        const double slices = cellsAlong(stock.to - stock.from, res);
        if (slices * segments > static_cast<double>(settings.maxCells)) {
            error =
                tooManyCells(slices * segments, settings, (stock.to - stock.from) * circumference);
            return std::nullopt;
        }
        model.profile_.emplace(stock.radius, stock.from, stock.to, static_cast<int>(slices));
        if (!stock.outline.empty() && !model.profile_->shapeBlank(stock.outline)) {
            error = "the blank's outline winds over the bar too often to be simulated";
            return std::nullopt;
        }
        model.axial_ = std::clamp(stock.axis, 0, 2);
        model.radial_ = (model.axial_ + 1) % 3;
        model.segments_ = segments;
        return model;
    }
    error =
        "the process has no stock in its machine configuration (stock = block ... or cylinder ...)";
    return std::nullopt;
}

bool PartModel::cut(const std::array<double, 3>& a, const std::array<double, 3>& b,
                    const Cutter& tool) {
    if (field_) return field_->cut(a, b, tool.radius);
    const auto axial = static_cast<std::size_t>(axial_), radial = static_cast<std::size_t>(radial_);
    return profile_->cut(a[axial], a[radial], b[axial], b[radial], tool);
}

bool PartModel::touches(const std::array<double, 3>& a, const std::array<double, 3>& b,
                        const Cutter& tool, double margin) const {
    if (field_) return field_->touches(a, b, tool.radius, margin);
    const auto axial = static_cast<std::size_t>(axial_), radial = static_cast<std::size_t>(radial_);
    return profile_->touches(a[axial], a[radial], b[axial], b[radial], tool, margin);
}

const DevelopedSurface* PartModel::makeJacket(std::string& note) {
    note.clear();
    if (jacket_) return &*jacket_;
    if (!profile_) {
        note = "the height field has no cylinder jacket";
        return nullptr;
    }
    // Columns of at most the resolution on the bar; fewer when that would
    // pass the cell cap, but never fewer than the turned part's facets
    // (slices x facets fit: create() checked it).
    const double wanted = DevelopedSurface::columnsFor(profile_->stockRadius(), resolution_);
    const double fitting = std::floor(static_cast<double>(maxCells_) / profile_->slices());
    const double columns = std::max(std::min(wanted, fitting), static_cast<double>(segments_));
    if (columns < wanted) {
        const double width = 2.0 * curve::kPi * profile_->stockRadius() / columns;
        note = "the developed surface has " + std::to_string(static_cast<long long>(columns)) +
               " columns (" + millimetres(std::ceil(width * 1000.0) / 1000.0) +
               " mm on the bar) instead of " + std::to_string(static_cast<long long>(wanted)) +
               ": at most " + std::to_string(maxCells_) + " cells are simulated";
    }
    jacket_.emplace(*profile_, static_cast<int>(columns));
    return &*jacket_;
}

bool PartModel::cutJacket(const JacketPoint& a, const JacketPoint& b, double toolRadius) {
    return jacket_ && profile_ && jacket_->cut(a, b, toolRadius, *profile_);
}

bool PartModel::touchesJacket(const JacketPoint& a, const JacketPoint& b, double toolRadius,
                              double margin) const {
    return jacket_ && profile_ && jacket_->touches(a, b, toolRadius, margin, *profile_);
}

double PartModel::developedVolume() const {
    return jacket_ && profile_ ? jacket_->removedVolume(*profile_) : 0.0;
}

double PartModel::removedVolume() const {
    if (field_) return field_->removedVolume();
    return profile_->removedVolume() + developedVolume();
}

double PartModel::blankVolume() const {
    if (field_) {
        const Box& b = field_->stock();
        return (b.max[0] - b.min[0]) * (b.max[1] - b.min[1]) * (b.max[2] - b.min[2]);
    }
    return profile_->blankVolume();
}

std::uint64_t PartModel::cells() const {
    if (field_)
        return static_cast<std::uint64_t>(field_->columns()) *
               static_cast<std::uint64_t>(field_->rows());
    return static_cast<std::uint64_t>(profile_->slices()) * static_cast<std::uint64_t>(segments_);
}

RemovalSettings fittingSettings(const Stock& stock, bool turning, std::uint64_t maxCells) {
    RemovalSettings settings;
    settings.maxCells = maxCells;
    for (double resolution : {0.2, 0.3, 0.5, 1.0, 2.0, 5.0, 10.0}) {
        settings.resolution = resolution;
        std::string error;
        if (PartModel::create(stock, settings, turning, error)) break;
    }
    return settings;
}

}  // namespace mtc::core::removal
