#include "InterpTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "resources/EmbeddedResources.h"

namespace mtc::test {

using namespace mtc::core;

MachineConfig cellFromText(const std::string& text) {
    auto result = readMachineConfig(text);
    for (const auto& d : result.diagnostics.items())
        ADD_FAILURE() << formatDiagnostic(d);
    return result.config;
}

const MachineConfig& demoCell() {
    static const MachineConfig cell =
        cellFromText(std::string(mtc::resources::find(mtc::resources::kDemoCellName)));
    return cell;
}

ProgramPtr parse(const std::string& source, int number) {
    ParseOptions options;
    options.programNumber = number;
    auto program = std::make_shared<Program>(parseProgram(source, options));
    program->number = number;
    return program;
}

std::string number(double value) {
    char text[40];
    if (std::fabs(value) < 0.00005) value = 0.0;
    std::snprintf(text, sizeof text, "%.4f", value);
    return text;
}

std::string where(const SourceLocation& location) {
    std::string text = location.block.empty() ? "-" : location.block;
    text += " L" + std::to_string(location.line);
    if (location.program != 0) text = "P" + std::to_string(location.program) + " " + text;
    return text;
}

void TranscriptSink::motion(const Motion& m) {
    static const char* const kType[] = {"rapid", "linear", "cw", "ccw"};
    text += "motion " + where(m.where) + (m.inserted ? " inserted " : " ") +
            kType[static_cast<int>(m.type)];
    bool moved = false, offset = false;
    std::string programmed, tool;
    for (int a = 0; a < m.axisCount; ++a) {
        if (std::fabs(m.end[a] - m.start[a]) < 1e-9) continue;
        const std::string name = " " + names_[static_cast<size_t>(a)] + "=";
        text += name + number(m.end[a]);
        programmed += name + number(programmedEndOf(m, a));
        tool += name + number(toolCentreOf(m, a));
        offset = offset || (m.compensated && m.toolOffset[static_cast<size_t>(a)] != 0.0);
        moved = true;
    }
    if (!moved) text += " (no axis moves)";
    if (m.planeAxis1 >= 0)
        text += " centre " + names_[static_cast<size_t>(m.planeAxis1)] + "=" + number(m.center1) +
                " " + names_[static_cast<size_t>(m.planeAxis2)] + "=" + number(m.center2);
    if (m.type != MotionType::Rapid) text += " F=" + number(m.feed);
    if (m.transformation != 30)
        text += " G" + std::to_string(m.transformation) +
                (m.transformation == 32 ? " RI=" + number(m.effectiveRadius) : "");
    // Tool compensation: the programmed end point and, when the tool centre is
    // not the axis position (length, edge), the tool centre.
    if (m.compensated && moved) text += " | programmed" + programmed;
    if (offset) text += " | tool centre" + tool;
    text += "\n";
}

void TranscriptSink::auxiliary(const AuxOutput& a) {
    text += "aux " + where(a.where) + " " + std::string(1, a.type);
    if (a.type == 'S')
        text += std::to_string(a.spindle) + "=" + number(a.value);
    else
        text += std::to_string(static_cast<long long>(a.value));
    text += "\n";
}

void TranscriptSink::dwell(const SourceLocation& w, double seconds) {
    text += "dwell " + where(w) + " " + number(seconds) + "\n";
}

void TranscriptSink::command(const MachineCommand& c) {
    text += "command " + where(c.where) + " " + commandText(c) + "\n";
}

std::string diagnosticsText(const DiagnosticList& diagnostics) {
    std::string text;
    for (const auto& d : diagnostics.items()) {
        text += d.severity == Severity::Error ? "error " : "warning ";
        text += d.code + " " + where(d.where);
        if (d.where.column) text += " C" + std::to_string(d.where.column);
        text += ": " + d.message;
        for (const auto& detail : d.details)
            text += " | " + detail;
        text += "\n";
    }
    return text;
}

std::string stateText(const Interpreter& interpreter) {
    const InterpreterState& s = interpreter.state();
    std::string text = "state g";
    for (int g : usedGGroups())
        text += " " + std::to_string(g) + "=" + std::to_string(s.modal.g[g]);
    text += "\nstate m";
    for (int g = 1; g <= 16; ++g)
        text += " " + std::to_string(g) + "=" + std::to_string(s.mGroups[g]);
    text += " q=" + std::to_string(s.lastQ);
    text += "\nstate t=" + std::to_string(s.modal.tool) + " e=" + std::to_string(s.modal.edge) +
            " f=" + number(s.modal.feed) + " s=";
    for (int j = 1; j < kSpindleSlots; ++j)
        text += (j > 1 ? "," : "") + number(s.modal.spindleSpeed[j]);
    text += " ri=" + number(s.modal.transformation.effectiveRadius()) + "\nstate machine";
    for (int a = 0; a < interpreter.axes().count(); ++a)
        text += " " + interpreter.axisName(a) + "=" + number(s.modal.machine[a]);
    const auto axes = interpreter.axisPositions();
    bool compensated = false;
    for (int a = 0; a < interpreter.axes().count(); ++a)
        compensated = compensated || std::fabs(axes[a] - s.modal.machine[a]) > 5e-5;
    if (compensated) {  // tool compensation: where the axes stand
        text += "\nstate axes";
        for (int a = 0; a < interpreter.axes().count(); ++a)
            text += " " + interpreter.axisName(a) + "=" + number(axes[a]);
    }
    text += "\nstate programmed";
    for (int a = 0; a < interpreter.axes().count(); ++a)
        text += " " + interpreter.axisName(a) + "=" + number(interpreter.programmedPosition(a));
    text += "\nstate definitions";
    for (int a = 0; a < interpreter.axes().count(); ++a)
        text +=
            " " + interpreter.axisName(a) + ":" + definitionLetter(s.modal.plane.definitionOf(a));
    text += "\nstate page60 rotary=";
    for (int j = 1; j <= 3; ++j)
        text += (j > 1 ? "," : "") + std::to_string(s.modal.rotaryAxisMode[static_cast<size_t>(j)]);
    text += " transformation=" + std::to_string(s.modal.transformation.kind()) + " tools=";
    for (int t = 0; t < kToolSpindles; ++t)
        text += (t > 0 ? "," : "") + std::to_string(s.modal.toolSpindle[static_cast<size_t>(t)]);
    text += "\nstate variables";
    for (int i = 0; i < kVariableCount; ++i)
        if (s.variables.written.test(static_cast<size_t>(i)))
            text +=
                " @" + std::to_string(i) + "=" + number(s.variables.values[static_cast<size_t>(i)]);
    text += "\nstate stack";
    for (const auto& level : interpreter.callStack())
        text += " P" + std::to_string(level.program) + ":" +
                (level.block.empty() ? "-" : level.block) + ":L" + std::to_string(level.line);
    return text + "\n";
}

Station::Station(const MachineConfig& cell, int process) : config(*cell.process(process)) {
    sink = std::make_unique<TranscriptSink>(std::vector<std::string>{});
    interpreter = std::make_unique<Interpreter>(config, store, *sink);
    auto* data = dynamic_cast<MachineDataStore*>(&interpreter->machineData());
    if (data) afc = std::make_shared<AdaptiveFeedControl>(config, *data);
    interpreter->setAdaptiveFeed(afc);
    std::vector<std::string> names;
    for (int a = 0; a < interpreter->axes().count(); ++a)
        names.push_back(interpreter->axisName(a));
    sink->setNames(names);
}

ProgramPtr Station::add(const std::string& source, int number) {
    ProgramPtr program = parse(source, number);
    store.put(config.index, number, program);
    return program;
}

RunResult Station::run(const std::string& source, int number, std::uint64_t budget) {
    add(source, number);
    DiagnosticList selectDiagnostics;
    if (!interpreter->select(number, 0, &selectDiagnostics)) {
        RunResult failed;
        failed.status = RunStatus::Error;
        failed.diagnostics = selectDiagnostics;
        return failed;
    }
    return interpreter->run(budget);
}

std::vector<std::string> errorCodes(const DiagnosticList& diagnostics) {
    std::vector<std::string> codes;
    for (const auto& d : diagnostics.items())
        if (d.severity == Severity::Error) codes.push_back(d.code);
    return codes;
}

}  // namespace mtc::test
