#include "cnc_core/tooldata/ToolList.h"

#include <algorithm>
#include <tuple>

namespace mtc::core {

namespace {

auto edgeFields(const ToolEdge& e) {
    return std::tie(e.edge, e.radius, e.radiusWear, e.length1, e.length2, e.length3, e.length1Wear,
                    e.length2Wear, e.length3Wear, e.orientation, e.cornerAngle, e.settingAngle);
}

}  // namespace

double ToolEdge::totalLength(int i) const {
    switch (i) {
        case 1:
            return length1 + length1Wear;
        case 2:
            return length2 + length2Wear;
        case 3:
            return length3 + length3Wear;
        default:
            return 0.0;
    }
}

const ToolEdge* Tool::edge(int e) const {
    if (e == 0) return edges.empty() ? nullptr : &edges.front();
    for (const ToolEdge& candidate : edges)
        if (candidate.edge == e) return &candidate;
    return nullptr;
}

ToolList ToolList::fromConfig(const ProcessConfig& process) {
    ToolList list;
    const bool milling = process.defaultPlane() == 17;
    for (const ToolConfig& config : process.tools) {
        ToolEdge edge;
        edge.edge = 1;
        edge.radius = config.radius;
        edge.orientation = config.edgeOrientation;
        // TOOL-002: the length along the tool's own axis. A milling tool
        // points along the perpendicular axis (L3); on a lathe a turning tool
        // sits radially in the turret, along X = the 2nd axis of G18 (L2),
        // and a driven or axial tool (edge 0 or 9) is fed along the axis
        // perpendicular to the plane it works in (L3: X under G20 Z C X).
        const bool turning = config.edgeOrientation >= 1 && config.edgeOrientation <= 8;
        (!milling && turning ? edge.length2 : edge.length3) = config.length;
        list.setEdge(config.number, edge, config.name);
    }
    return list;
}

const Tool* ToolList::find(int number) const {
    auto it = std::lower_bound(tools_.begin(), tools_.end(), number,
                               [](const Tool& t, int n) { return t.number < n; });
    return it != tools_.end() && it->number == number ? &*it : nullptr;
}

const ToolEdge* ToolList::edge(int number, int edge) const {
    const Tool* tool = find(number);
    return tool ? tool->edge(edge) : nullptr;
}

Tool& ToolList::toolFor(int number) {
    auto it = std::lower_bound(tools_.begin(), tools_.end(), number,
                               [](const Tool& t, int n) { return t.number < n; });
    if (it != tools_.end() && it->number == number) return *it;
    Tool tool;
    tool.number = number;
    return *tools_.insert(it, tool);
}

void ToolList::setEdge(int number, const ToolEdge& data, const std::string& name) {
    Tool& tool = toolFor(number);
    if (!name.empty()) tool.name = name;
    auto it = std::lower_bound(tool.edges.begin(), tool.edges.end(), data.edge,
                               [](const ToolEdge& e, int n) { return e.edge < n; });
    if (it != tool.edges.end() && it->edge == data.edge)
        *it = data;
    else
        tool.edges.insert(it, data);
}

bool ToolList::removeTool(int number) {
    auto it = std::find_if(tools_.begin(), tools_.end(),
                           [number](const Tool& t) { return t.number == number; });
    if (it == tools_.end()) return false;
    tools_.erase(it);
    return true;
}

bool ToolList::removeEdge(int number, int edge) {
    auto tool = std::find_if(tools_.begin(), tools_.end(),
                             [number](const Tool& t) { return t.number == number; });
    if (tool == tools_.end()) return false;
    auto it = std::find_if(tool->edges.begin(), tool->edges.end(),
                           [edge](const ToolEdge& e) { return e.edge == edge; });
    if (it == tool->edges.end()) return false;
    tool->edges.erase(it);
    if (tool->edges.empty()) tools_.erase(tool);
    return true;
}

bool ToolList::rename(int number, const std::string& name) {
    auto it = std::find_if(tools_.begin(), tools_.end(),
                           [number](const Tool& t) { return t.number == number; });
    if (it == tools_.end()) return false;
    it->name = name;
    return true;
}

bool ToolList::operator==(const ToolList& other) const {
    if (tools_.size() != other.tools_.size()) return false;
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        const Tool& a = tools_[i];
        const Tool& b = other.tools_[i];
        if (a.number != b.number || a.name != b.name || a.edges.size() != b.edges.size())
            return false;
        for (std::size_t k = 0; k < a.edges.size(); ++k)
            if (edgeFields(a.edges[k]) != edgeFields(b.edges[k])) return false;
    }
    return true;
}

}  // namespace mtc::core
