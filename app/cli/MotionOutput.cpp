#include "cli/MotionOutput.h"

#include <cmath>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/machine/SimulatedMachine.h"

namespace mtc::cli {

namespace {

const std::string kNoName;

bool isArc(core::MotionType type) {
    return type == core::MotionType::ArcCW || type == core::MotionType::ArcCCW;
}

}  // namespace

MotionOutput::MotionOutput(MotionMode mode, JsonWriter* json, std::FILE* text)
    : mode_(mode), json_(json), text_(text) {}

const char* MotionOutput::typeName(core::MotionType type) {
    switch (type) {
        case core::MotionType::Rapid:
            return "rapid";
        case core::MotionType::Linear:
            return "linear";
        case core::MotionType::ArcCW:
            return "cw";
        case core::MotionType::ArcCCW:
            return "ccw";
    }
    return "linear";
}

const std::string& MotionOutput::axisName(int index) const {
    if (index < 0 || static_cast<std::size_t>(index) >= names_.size()) return kNoName;
    return names_[static_cast<std::size_t>(index)];
}

bool MotionOutput::adaptedMotion(const core::Motion&) {
    return machine_ && afc_ && machine_->lastMoveReportsAfc();
}

void MotionOutput::motion(const core::Motion& motion) {
    ++motions_;
    if (mode_ == MotionMode::None) return;  // adapted_ and stopped_ are the writers'
    adapted_ = adaptedMotion(motion);
    stopped_ = adapted_ && machine_->lastMoveFraction() < 1.0;
    const core::Motion* written = &motion;
    core::Motion reached;
    if (stopped_) {  // AFC-012: the record shows where the axes stopped
        reached = motion;
        for (int i = 0; i < motion.axisCount && i < core::kMaxAxes; ++i)
            reached.end[static_cast<std::size_t>(i)] =
                machine_->lastMoveEnd()[static_cast<std::size_t>(i)];
        written = &reached;
    }
    if (mode_ == MotionMode::Json && json_ != nullptr) writeJson(*written);
    if (mode_ == MotionMode::Text && text_ != nullptr) writeText(*written);
}

void MotionOutput::auxiliary(const core::AuxOutput&) {
    ++auxiliaries_;
}

void MotionOutput::dwell(const core::SourceLocation&, double seconds) {
    ++dwells_;
    dwellSeconds_ += seconds;
}

void MotionOutput::command(const core::MachineCommand&) {
    ++commands_;
}

void MotionOutput::writeJson(const core::Motion& m) {
    JsonWriter& json = *json_;
    json.beginObject();
    json.key("program");
    json.value(m.where.program);
    json.key("block");
    json.value(m.where.block);
    json.key("line");
    json.value(m.where.line);
    json.key("type");
    json.value(typeName(m.type));
    if (m.inserted) {
        json.key("inserted");
        json.value(true);
    }
    // Under tool compensation "end" is the programmed end point, "tool_end"
    // the tool centre and "axis_end" where the axes go when the tool centre
    // is not the axis position (tool length, cutting edge of a turning tool).
    writeAxes("end", m, [&](int axis) { return core::programmedEndOf(m, axis); });
    bool offset = false;
    for (int i = 0; i < m.axisCount && i < core::kMaxAxes; ++i)
        offset = offset || (m.compensated && m.toolOffset[static_cast<std::size_t>(i)] != 0.0);
    if (m.compensated)
        writeAxes("tool_end", m, [&](int axis) { return core::toolCentreOf(m, axis); });
    if (offset)
        writeAxes("axis_end", m, [&](int axis) { return m.end[static_cast<std::size_t>(axis)]; });
    if (isArc(m.type)) {  // the programmed circle's centre (the tool centre's circle is concentric)
        json.key("center");
        json.beginObject();
        if (!axisName(m.planeAxis1).empty()) {
            json.key(axisName(m.planeAxis1));
            json.value(centreOf(m, m.planeAxis1, m.center1));
        }
        if (!axisName(m.planeAxis2).empty()) {
            json.key(axisName(m.planeAxis2));
            json.value(centreOf(m, m.planeAxis2, m.center2));
        }
        json.endObject();
    }
    json.key("feed");
    json.value(m.feed);
    if (adapted_) {
        json.key("afc_feed");
        json.value(machine_->lastMoveFeed());
    }
    if (stopped_) {
        json.key("afc_stopped");
        json.value(true);
    }
    json.endObject();
}

double MotionOutput::centreOf(const core::Motion& m, int axis, double centre) {
    if (!m.compensated || axis < 0 || axis >= core::kMaxAxes) return centre;
    return centre - m.toolOffset[static_cast<std::size_t>(axis)];
}

void MotionOutput::writeAxes(const char* key, const core::Motion& m,
                             const std::function<double(int)>& value) {
    JsonWriter& json = *json_;
    json.key(key);
    json.beginObject();
    for (int i = 0; i < m.axisCount && i < core::kMaxAxes; ++i) {
        const std::string& name = axisName(i);
        if (name.empty()) continue;
        json.key(name);
        json.value(value(i));
    }
    json.endObject();
}

void MotionOutput::appendAxisValue(int axis, double value) {
    const std::string& name = axisName(axis);
    if (name.empty()) return;
    line_ += ' ';
    line_ += name;
    line_ += '=';
    JsonWriter::appendNumber(line_, value);
}

void MotionOutput::writeText(const core::Motion& m) {
    line_ = "P" + std::to_string(m.where.program) + ' ';
    line_ += m.where.block.empty() ? "-" : m.where.block;
    line_ +=
        " L" + std::to_string(m.where.line) + (m.inserted ? " inserted " : " ") + typeName(m.type);
    for (int i = 0; i < m.axisCount && i < core::kMaxAxes; ++i)
        appendAxisValue(i, core::programmedEndOf(m, i));
    if (isArc(m.type)) {
        line_ += " centre";
        appendAxisValue(m.planeAxis1, centreOf(m, m.planeAxis1, m.center1));
        appendAxisValue(m.planeAxis2, centreOf(m, m.planeAxis2, m.center2));
    }
    if (m.compensated) {  // tool compensation: the tool centre
        line_ += " tool";
        for (int i = 0; i < m.axisCount && i < core::kMaxAxes; ++i)
            appendAxisValue(i, core::toolCentreOf(m, i));
    }
    if (m.type != core::MotionType::Rapid) {
        line_ += " F=";
        JsonWriter::appendNumber(line_, m.feed);
    }
    if (adapted_) {
        line_ += " AFC F=";
        JsonWriter::appendNumber(line_, std::round(machine_->lastMoveFeed() * 10.0) / 10.0);
    }
    if (stopped_) line_ += " stopped";
    line_ += '\n';
    std::fwrite(line_.data(), 1, line_.size(), text_);
}

}  // namespace mtc::cli
