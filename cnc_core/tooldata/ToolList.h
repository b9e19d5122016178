#pragma once

#include <string>
#include <vector>

#include "cnc_core/machine/MachineConfig.h"

/// Tool and zero offset data of the cell as core data (issue 16 §4): the
/// tool list of each process and the zero offset tables, persisted beside
/// the machine data (docs/TOOL-DATA.md, docs/decisions/tool-data.md).
namespace mtc::core {

/// One cutting edge E of a tool (seed 001 ch. 3: edge orientation, radius,
/// corner and setting angle; seed 003 ch. 3.6: radius and the lengths L1,
/// L2 in the working plane and L3 on the perpendicular axis, each as
/// geometry + wear).
struct ToolEdge {
    int edge = 1;              ///< E 1..9
    double radius = 0.0;       ///< mm, 0 .. 999.99999
    double radiusWear = 0.0;   ///< mm
    double length1 = 0.0;      ///< L1, mm (abscissa of the working plane)
    double length2 = 0.0;      ///< L2, mm (ordinate)
    double length3 = 0.0;      ///< L3, mm (perpendicular axis: the milling tool's length)
    double length1Wear = 0.0;  ///< mm
    double length2Wear = 0.0;
    double length3Wear = 0.0;
    int orientation = 0;        ///< cutting edge position 0..9 (turning tools)
    double cornerAngle = 0.0;   ///< degrees, 0 .. 180
    double settingAngle = 0.0;  ///< degrees, 0 .. 360

    /// R = geometry + wear, L_i = geometry + wear (seed 003 ch. 3.6, without
    /// the tool offsets and D corrections the simulator does not have).
    double totalRadius() const { return radius + radiusWear; }
    double totalLength(int i) const;
};

/// One tool T of a process's tool list.
struct Tool {
    int number = 0;  ///< T 1..9999999
    std::string name;
    std::vector<ToolEdge> edges;  ///< sorted by edge number, at least one

    const ToolEdge* edge(int e) const;
};

/// The tool list of one process, sorted by tool number.
class ToolList {
  public:
    /// The list the machine configuration gives (`[process N tools]`): one
    /// edge E1 per tool with its radius, edge orientation and length; the
    /// length is L2 for a turning tool (orientation 1..8) of a process whose
    /// default plane is not G17 (radial in the turret: X under G18), L3
    /// otherwise (TOOL-002).
    static ToolList fromConfig(const ProcessConfig& process);

    const std::vector<Tool>& tools() const { return tools_; }
    bool empty() const { return tools_.empty(); }
    const Tool* find(int number) const;
    /// Edge `edge` of tool `number` (edge 0 = the first edge), or nullptr.
    const ToolEdge* edge(int number, int edge) const;
    /// Adds or replaces edge `data.edge` of tool `number` (name kept when
    /// `name` is empty).
    void setEdge(int number, const ToolEdge& data, const std::string& name = {});
    /// Removes tool `number` (every edge) or one of its edges; false when absent.
    bool removeTool(int number);
    bool removeEdge(int number, int edge);
    /// Changes the name of an existing tool; false when absent.
    bool rename(int number, const std::string& name);

    bool operator==(const ToolList& other) const;

  private:
    Tool& toolFor(int number);
    std::vector<Tool> tools_;
};

}  // namespace mtc::core
