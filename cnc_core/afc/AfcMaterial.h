#pragma once

#include <array>

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/toolpath/Stock.h"

namespace mtc::core {

/// Share of a move's path (0..1) that lies in the raw part: from `from` to
/// `to`; from >= to when the whole move is in air.
struct MaterialShare {
    double from = 0.0;
    double to = 0.0;
};

/// Where the raw part (`stock =` of the process) is along moves, so that
/// adaptive feed control knows when the tool cuts and when it moves in air
/// (docs/decisions/machine-data.md AFC-017). The stock is in machine
/// coordinates of the linear axes with base definition X, Y, Z, as the
/// toolpath view draws it; tool length is not compensated.
class AfcMaterial {
  public:
    explicit AfcMaterial(const ProcessConfig& config);

    /// The process has a stock: shares are known.
    bool known() const { return stock_.shape != Stock::Shape::None; }
    /// The part of `motion`'s path inside the stock (straight moves exactly;
    /// arcs from 32 points along the arc, the raw parts being convex).
    MaterialShare along(const Motion& motion) const;

  private:
    std::array<double, 3> scenePoint(const std::array<double, kMaxAxes>& machine) const;
    bool inside(const std::array<double, 3>& point) const;
    /// Where an arc's 32 points cannot all be decided by its bounding box.
    MaterialShare alongArc(const Motion& motion) const;
    MaterialShare alongLine(const std::array<double, 3>& a, const std::array<double, 3>& b) const;

    Stock stock_;
    std::array<int, 3> axisOfScene_{-1, -1, -1};  ///< machine axis drawn as X, Y, Z
};

}  // namespace mtc::core
