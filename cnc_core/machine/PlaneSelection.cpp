#include "cnc_core/machine/PlaneSelection.h"

#include <cmath>
#include <iterator>

namespace mtc::core {
namespace {

constexpr AxisDefinition kTarget[3] = {AxisDefinition::X, AxisDefinition::Y, AxisDefinition::Z};
const char* const kRole[3] = {"1st axis of the plane", "2nd axis of the plane",
                              "perpendicular axis"};

std::string nameOf(const ProcessAxes& axes, int axis) {
    const AxisModel& m = axes.axis(axis);
    return m.name.valid() ? m.name.toString() : m.configName;
}

void checkCount(const std::vector<FreePlaneAxis>& programmed, std::vector<PlaneProblem>& problems) {
    if (programmed.size() < 2)
        problems.push_back({"G20_AXIS_COUNT",
                            "G20 needs two or three axes (1st, 2nd plane axis, perpendicular)", 0});
    if (programmed.size() > 3)
        problems.push_back({"G20_EXTRA_AXIS",
                            "a G20 block may hold no axis words besides the 2 or 3 G20 axes",
                            programmed[3].column});
}

void checkEachAxis(const ProcessAxes& axes, const std::vector<FreePlaneAxis>& programmed,
                   std::vector<PlaneProblem>& problems) {
    const size_t n = programmed.size() < 3 ? programmed.size() : 3;
    for (size_t i = 0; i < n; ++i) {
        const FreePlaneAxis& p = programmed[i];
        const AxisModel& model = axes.axis(p.axis);
        const std::string name = nameOf(axes, p.axis);
        for (size_t j = 0; j < i; ++j)
            if (programmed[j].axis == p.axis)
                problems.push_back(
                    {"G20_AXIS_TWICE", "axis " + name + " occurs twice in G20", p.column});
        if (p.value != 0.0)
            problems.push_back({"G20_AXIS_VALUE",
                                "every G20 axis must be written with the value 0 (" + name + ")",
                                p.column});
        if (model.spindle && !model.rotary)
            problems.push_back(
                {"G20_SPINDLE", "spindle " + name + " cannot span a plane", p.column});
        if (!model.allows(kTarget[i]))
            problems.push_back({"G20_DEFINITION_NOT_ALLOWED",
                                std::string("axis ") + name + " may not become the " + kRole[i] +
                                    " (definition " + definitionLetter(kTarget[i]) +
                                    " is not among its axis definitions Cxx.053)",
                                p.column});
        if (i == 2 && model.rotary)
            problems.push_back({"G20_PERPENDICULAR_ROTARY",
                                "the perpendicular axis " + name + " must be a linear axis",
                                p.column});
    }
}

}  // namespace

PlaneSelection PlaneSelection::base(const ProcessAxes& axes, int plane) {
    PlaneSelection selection;
    selection.axisOfDefinition_.fill(-1);
    selection.definitionOfAxis_.fill(AxisDefinition::None);
    for (int i = 0; i < axes.count(); ++i) {
        const AxisDefinition d = axes.axis(i).baseDefinition();
        if (d != AxisDefinition::None && selection.axisOf(d) < 0) selection.assign(i, d);
    }
    selection.plane_ = static_cast<std::int8_t>(plane == 18 || plane == 19 ? plane : 17);
    return selection;
}

std::vector<PlaneProblem> PlaneSelection::selectStandard(const ProcessAxes& axes, int plane) {
    PlaneSelection next = base(axes, plane);
    std::vector<PlaneProblem> problems;
    const auto defs = next.planeDefinitions();
    for (int i = 0; i < 2; ++i)
        if (next.axisOf(defs[static_cast<size_t>(i)]) < 0)
            problems.push_back({"PLANE_AXIS_MISSING",
                                "G" + std::to_string(plane) + " needs an axis with definition " +
                                    definitionLetter(defs[static_cast<size_t>(i)]),
                                0});
    if (problems.empty()) *this = next;
    return problems;
}

std::vector<PlaneProblem> PlaneSelection::selectFree(const ProcessAxes& axes,
                                                     const std::vector<FreePlaneAxis>& programmed) {
    std::vector<PlaneProblem> problems;
    checkCount(programmed, problems);
    checkEachAxis(axes, programmed, problems);
    if (!problems.empty()) return problems;
    // From the allocation in force (seed 003, 5.1: only power-up, reset,
    // program end, jog reset and G17/G18/G19 restore the base system), so a
    // two-axis G20 keeps the current perpendicular axis (3.2).
    PlaneSelection next = *this;
    // checkCount refused more than three; the bound keeps kTarget's index safe anyway.
    for (size_t i = 0; i < std::size(kTarget) && i < programmed.size(); ++i) {
        const int axis = programmed[i].axis;
        const AxisDefinition target = kTarget[i];
        const int holder = next.axisOf(target);
        if (holder == axis) continue;
        const AxisDefinition previous = next.definitionOf(axis);
        if (previous != AxisDefinition::None)
            next.axisOfDefinition_[static_cast<size_t>(previous)] = -1;
        next.assign(axis, target);
        if (holder >= 0) {
            next.definitionOfAxis_[static_cast<size_t>(holder)] = AxisDefinition::None;
            if (previous != AxisDefinition::None) next.assign(holder, previous);
        }
    }
    const int perpendicular = next.axisOf(AxisDefinition::Z);
    if (programmed.size() == 2 && perpendicular >= 0 && axes.axis(perpendicular).rotary) {
        problems.push_back({"G20_PERPENDICULAR_ROTARY",
                            "the axis left perpendicular to the plane, " +
                                nameOf(axes, perpendicular) +
                                ", is a rotary axis; name a linear perpendicular axis as the "
                                "third G20 axis",
                            programmed[1].column});
        return problems;
    }
    next.plane_ = 20;
    *this = next;
    return problems;
}

bool PlaneSelection::isBase(const ProcessAxes& axes) const {
    for (int i = 0; i < axes.count(); ++i)
        if (definitionOfAxis_[static_cast<size_t>(i)] != axes.axis(i).baseDefinition())
            return false;
    return true;
}

void PlaneSelection::assign(int axis, AxisDefinition definition) {
    // None has no column in axisOfDefinition_ (index -1): only the axis side changes.
    if (definition != AxisDefinition::None)
        axisOfDefinition_[static_cast<size_t>(definition)] = static_cast<std::int8_t>(axis);
    definitionOfAxis_[static_cast<size_t>(axis)] = definition;
}

}  // namespace mtc::core
