#include "cli/StateOutput.h"

#include <cmath>
#include <string>

#include "cnc_core/interp/ModalGroups.h"
#include "cnc_core/machine/AxisNameTable.h"

namespace mtc::cli {

namespace {

constexpr int kReportedMGroups = 15;  ///< contract: groups 1..15

template <typename Array>
void writeNumberArray(JsonWriter& json, const Array& values, std::size_t first, std::size_t count) {
    json.beginArray();
    for (std::size_t i = first; i < first + count && i < values.size(); ++i)
        json.value(values[i]);
    json.endArray();
}

void writeGroups(JsonWriter& json, const core::InterpreterState& state) {
    json.key("g");
    json.beginObject();
    for (int group : core::usedGGroups()) {
        const int value = state.modal.g[static_cast<std::size_t>(group)];
        if (value < 0) continue;
        json.key(std::to_string(group));
        json.value(value);
    }
    json.endObject();
    json.key("m_groups");
    json.beginObject();
    for (int group = 1; group <= kReportedMGroups; ++group) {
        json.key(std::to_string(group));
        json.value(state.mGroups[static_cast<std::size_t>(group)]);
    }
    json.endObject();
}

void writePages(JsonWriter& json, const StateView& view) {
    const core::ModalState& modal = view.state.modal;
    json.key("page61");
    json.beginObject();
    json.key("m16");
    writeNumberArray(json, view.page61.m16, 0, view.page61.m16.size());
    json.key("q");
    writeNumberArray(json, view.page61.q, 0, view.page61.q.size());
    json.endObject();
    json.key("page60");
    json.beginObject();
    json.key("rotary_axis_mode");
    writeNumberArray(json, modal.rotaryAxisMode, 1, 3);
    json.key("transformation");
    json.value(modal.transformation.kind());
    json.key("tool_spindle");
    writeNumberArray(json, modal.toolSpindle, 0, core::kToolSpindles);
    json.endObject();
}

void writeSpindles(JsonWriter& json, const StateView& view) {
    json.key("s");
    json.beginObject();
    for (const core::AxisModel& axis : view.axes.axes()) {
        if (!axis.spindle || axis.spindleIndex < 1 || axis.spindleIndex >= core::kSpindleSlots)
            continue;
        json.key("S" + std::to_string(axis.spindleIndex));
        json.value(view.state.modal.spindleSpeed[static_cast<std::size_t>(axis.spindleIndex)]);
    }
    json.endObject();
}

void writeVariables(JsonWriter& json, const core::Variables& variables) {
    json.key("variables");
    json.beginObject();
    for (int n = 0; n < core::kVariableCount; ++n) {
        if (!variables.written.test(static_cast<std::size_t>(n))) continue;
        json.key(std::to_string(n));
        json.value(variables.values[static_cast<std::size_t>(n)]);
    }
    json.endObject();
}

/// Name of the programmed position of axis `i` in the state's view:
/// designation 2 while G31/G32 of that state transforms it (I-013a).
std::string positionName(const StateView& view, std::size_t i) {
    return core::programmedAxisName(view.axes, view.state.modal.transformation,
                                    static_cast<int>(i));
}

void writePosition(JsonWriter& json, const StateView& view) {
    json.key("position");
    json.beginObject();
    for (std::size_t i = 0; i < view.axisNames.size() && i < view.positions.size(); ++i) {
        if (view.axisNames[i].empty()) continue;
        json.key(positionName(view, i));
        json.value(view.positions[i]);
    }
    json.endObject();
}

void writeAxisPositions(JsonWriter& json, const StateView& view) {
    if (view.axisPositions == nullptr || view.axisPositions->empty()) return;
    json.key("axis_position");
    json.beginObject();
    for (std::size_t i = 0; i < view.axisNames.size() && i < view.axisPositions->size(); ++i) {
        if (view.axisNames[i].empty()) continue;
        json.key(view.axisNames[i]);
        json.value((*view.axisPositions)[i]);
    }
    json.endObject();
}

void writeCallStack(JsonWriter& json, const core::InterpreterState& state) {
    json.key("call_stack");
    json.beginArray();
    for (const core::CallFrame& frame : state.callStack) {
        json.beginObject();
        json.key("program");
        json.value(frame.program ? frame.program->number : 0);
        json.key("block");
        json.value(frame.program ? frame.program->blockId(frame.callBlock) : std::string());
        json.key("line");
        const bool known = frame.program && frame.callBlock < frame.program->blocks.size();
        json.value(known ? static_cast<int>(frame.program->blocks[frame.callBlock].line) : 0);
        json.endObject();
    }
    json.endArray();
}

}  // namespace

std::vector<std::string> reportedAxisNames(const core::Interpreter& interpreter) {
    std::vector<std::string> names;
    const core::ProcessAxes& axes = interpreter.axes();
    for (int i = 0; i < axes.count(); ++i) {
        const core::AxisModel& axis = axes.axis(i);
        names.push_back(axis.spindle && !axis.rotary ? std::string() : interpreter.axisName(i));
    }
    return names;
}

std::vector<double> compensatedAxisPositions(const core::Interpreter& interpreter) {
    const auto axes = interpreter.axisPositions();
    const auto& machine = interpreter.state().modal.machine;
    bool differs = false;
    for (int i = 0; i < interpreter.axes().count(); ++i)
        differs = differs || std::abs(axes[static_cast<std::size_t>(i)] -
                                      machine[static_cast<std::size_t>(i)]) > 1e-9;
    if (!differs) return {};
    return std::vector<double>(axes.begin(), axes.begin() + interpreter.axes().count());
}

std::vector<double> programmedPositions(const core::Interpreter& interpreter) {
    std::vector<double> positions;
    for (int i = 0; i < interpreter.axes().count(); ++i)
        positions.push_back(interpreter.programmedPosition(i));
    return positions;
}

Page61Buffers readPage61(const core::MachineDataProvider& machineData, int process) {
    Page61Buffers buffers;
    for (int element = 1; element <= 40; ++element) {
        const auto index = static_cast<std::size_t>(element - 1);
        double value = 0.0;
        if (machineData.read({61, process, 1, element}, value) == core::MachineDataStatus::Ok)
            buffers.m16[index] = value;
        value = 0.0;
        if (machineData.read({61, process, 2, element}, value) == core::MachineDataStatus::Ok)
            buffers.q[index] = value;
    }
    return buffers;
}

void writeStateJson(JsonWriter& json, const StateView& view) {
    const core::ModalState& modal = view.state.modal;
    json.beginObject();
    writeGroups(json, view.state);
    writePages(json, view);
    writeSpindles(json, view);
    json.key("t");
    json.value(modal.tool);
    json.key("e");
    json.value(modal.edge);
    json.key("f");
    json.value(modal.feed);
    writeVariables(json, view.state.variables);
    writePosition(json, view);
    writeAxisPositions(json, view);
    writeCallStack(json, view.state);
    json.endObject();
}

void printStateText(std::FILE* stream, const StateView& view, const char* label) {
    const core::ModalState& modal = view.state.modal;
    std::string line = std::string(label) + ": G";
    for (int group : core::usedGGroups()) {
        const int value = modal.g[static_cast<std::size_t>(group)];
        if (value >= 0) line += " " + std::to_string(group) + ":G" + std::to_string(value);
    }
    line += "\n       M";
    for (int group = 1; group <= kReportedMGroups; ++group) {
        const int value = view.state.mGroups[static_cast<std::size_t>(group)];
        if (value >= 0) line += " " + std::to_string(group) + ":M" + std::to_string(value);
    }
    line += "\n       T=" + std::to_string(modal.tool) + " E=" + std::to_string(modal.edge) + " F=";
    JsonWriter::appendNumber(line, modal.feed);
    line += " transformation G" + std::to_string(modal.transformation.kind());
    line += "\n       position";
    for (std::size_t i = 0; i < view.axisNames.size() && i < view.positions.size(); ++i) {
        if (view.axisNames[i].empty()) continue;
        line += " " + positionName(view, i) + "=";
        JsonWriter::appendNumber(line, view.positions[i]);
    }
    if (view.axisPositions != nullptr && !view.axisPositions->empty()) {
        line += "\n       axis position (tool compensation)";
        for (std::size_t i = 0; i < view.axisNames.size() && i < view.axisPositions->size(); ++i) {
            if (view.axisNames[i].empty()) continue;
            line += " " + view.axisNames[i] + "=";
            JsonWriter::appendNumber(line, (*view.axisPositions)[i]);
        }
    }
    std::fprintf(stream, "%s\n", line.c_str());
}

}  // namespace mtc::cli
