#include "cnc_core/machine/ProcessAxes.h"

#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/machine/ConfigText.h"

namespace mtc::core {
namespace {

/// A configuration problem at `line` of the configuration file (0 = unknown).
void configError(DiagnosticList& diagnostics, int line, const std::string& code,
                 const std::string& message) {
    diagnostics.error(code, {0, "", line, 0}, message);
}

AxisModel modelOf(const AxisConfig& config, DiagnosticList& diagnostics) {
    AxisModel model;
    model.configName = config.name;
    model.configLine = config.line;
    model.spindle = config.kind == AxisKind::Spindle;
    model.spindleIndex = model.spindle ? config.spindleIndex : 0;
    model.rotary =
        config.kind == AxisKind::Rotary || (model.spindle && !config.rotaryAxisName.empty());
    model.endless = model.rotary && config.minPosition == 0.0 && config.maxPosition == 0.0;
    model.polarDirection = config.polarDirection;
    model.maxVelocity = config.maxVelocity;
    model.rapidSecondsPerUnit = config.maxVelocity > 0 ? 60.0 / config.maxVelocity : 0.0;
    model.minPosition = config.minPosition;
    model.maxPosition = config.maxPosition;
    const std::string programName = model.spindle ? config.rotaryAxisName : config.name;
    if (!programName.empty()) {
        model.name = AxisName::parse(programName);
        if (!model.name.valid() || definitionFromLetter(model.name.letter) == AxisDefinition::None)
            configError(
                diagnostics, config.line, "CFG_AXIS_NAME",
                "axis " + config.name + ": " + quotedValue(programName) + " is not an axis designation");
    }
    if (!config.designation2.empty()) {
        model.designation2 = AxisName::parse(config.designation2);
        if (!model.designation2.valid())
            configError(
                diagnostics, config.line, "CFG_AXIS_NAME",
                "axis " + config.name + ": bad designation 2 " + quotedValue(config.designation2));
    }
    if (model.spindle && !model.rotary) return model;  // a plain spindle has no feed definition
    for (const auto& text : config.definitions) {
        const AxisDefinition d =
            text.size() == 1 ? definitionFromLetter(text[0]) : AxisDefinition::None;
        if (d == AxisDefinition::None) {
            configError(
                diagnostics, config.line, "CFG_AXIS_DEFINITION",
                "axis " + config.name + ": " + quotedValue(text) + " is not an axis definition (X..C)");
            continue;
        }
        if (model.definitionCount < 4) model.definitions[model.definitionCount++] = d;
    }
    if (model.definitionCount == 0)
        configError(diagnostics, config.line, "CFG_AXIS_DEFINITION",
                    "axis " + config.name + " has no axis definition");
    return model;
}

void checkUnique(const std::vector<AxisModel>& axes, DiagnosticList& diagnostics) {
    std::vector<std::pair<AxisName, std::string>> names;
    for (const auto& a : axes) {
        for (AxisName n : {a.name, a.designation2}) {
            if (!n.valid()) continue;
            for (const auto& [other, owner] : names)
                if (other == n)
                    configError(diagnostics, a.configLine, "CFG_AXIS_DUPLICATE",
                                "designation " + n.toString() + " is used by " + owner + " and " +
                                    a.configName);
            names.emplace_back(n, a.configName);
        }
    }
    for (size_t i = 0; i < axes.size(); ++i)
        for (size_t j = i + 1; j < axes.size(); ++j)
            if (axes[i].baseDefinition() != AxisDefinition::None &&
                axes[i].baseDefinition() == axes[j].baseDefinition())
                configError(diagnostics, axes[j].configLine, "CFG_AXIS_DUPLICATE",
                            "axes " + axes[i].configName + " and " + axes[j].configName +
                                " have the same base definition " +
                                definitionLetter(axes[i].baseDefinition()));
}

}  // namespace

bool AxisModel::allows(AxisDefinition definition) const {
    for (int i = 0; i < definitionCount; ++i)
        if (definitions[static_cast<size_t>(i)] == definition) return true;
    return false;
}

ProcessAxes ProcessAxes::build(const ProcessConfig& config, DiagnosticList& diagnostics) {
    ProcessAxes result;
    for (const auto& axisConfig : config.axes) {
        if (result.count() == kMaxAxes) {
            configError(diagnostics, axisConfig.line, "CFG_AXIS_COUNT",
                        "more than " + std::to_string(kMaxAxes) + " axes in process " +
                            std::to_string(config.index) + "; the rest is ignored");
            break;
        }
        result.axes_.push_back(modelOf(axisConfig, diagnostics));
    }
    checkUnique(result.axes_, diagnostics);
    return result;
}

int ProcessAxes::findByName(AxisName name) const {
    for (int i = 0; i < count(); ++i)
        if (axes_[static_cast<size_t>(i)].name == name) return i;
    return -1;
}

int ProcessAxes::findByDesignation2(AxisName name) const {
    for (int i = 0; i < count(); ++i)
        if (axes_[static_cast<size_t>(i)].designation2 == name) return i;
    return -1;
}

int ProcessAxes::spindleAxis(int spindleIndex) const {
    for (int i = 0; i < count(); ++i)
        if (axes_[static_cast<size_t>(i)].spindle &&
            axes_[static_cast<size_t>(i)].spindleIndex == spindleIndex)
            return i;
    return -1;
}

}  // namespace mtc::core
