#include "cnc_core/restart/RestartStateCompare.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cnc_core/interp/ModalGroups.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {

namespace {

constexpr double kTolerance = 1e-6;

std::string numberText(double value) {
    return formatGeneral(value, 10);
}

std::string bufferText(const std::array<int, FunctionBuffer::kLength>& buffer) {
    std::string text;
    for (int value : buffer) {
        if (value == 0) break;
        text += (text.empty() ? "" : " ") + std::to_string(value);
    }
    return text.empty() ? "empty" : text;
}

std::string stackText(const InterpreterState& s) {
    std::string text;
    const auto at = [](const ProgramPtr& program, std::uint32_t block) {
        if (!program) return std::string("-");
        const std::string id = program->blockId(block);
        return "P" + std::to_string(program->number) + " " +
               (id.empty() ? "block " + std::to_string(block) : id);
    };
    for (const CallFrame& frame : s.callStack)
        text += at(frame.program, frame.callBlock) + " > ";
    return text + at(s.program, s.block);
}

/// Collects the differences of one comparison.
class Comparison {
  public:
    Comparison(const RestartStateView& expected, const RestartStateView& actual,
               const ProcessAxes& axes)
        : e_(expected), a_(actual), axes_(axes) {}

    void number(const std::string& what, double expected, double actual, double tolerance = 0.0) {
        const bool same =
            tolerance > 0.0 ? std::fabs(expected - actual) <= tolerance : expected == actual;
        if (same) return;
        out_.push_back({what, describeStateItem(what), true, expected, actual, numberText(expected),
                        numberText(actual)});
    }
    void text(const std::string& what, const std::string& expected, const std::string& actual) {
        if (expected == actual) return;
        out_.push_back({what, describeStateItem(what), false, 0.0, 0.0, expected, actual});
    }

    void gGroups() {
        for (int group : usedGGroups()) {
            const auto g = static_cast<std::size_t>(group);
            number("g" + std::to_string(group), e().modal.g[g], a().modal.g[g]);
        }
        for (int axis = 0; axis < axes_.count(); ++axis)
            number("plane." + axes_.axis(axis).displayName(),
                   static_cast<int>(e().modal.plane.definitionOf(axis)),
                   static_cast<int>(a().modal.plane.definitionOf(axis)));
        number("ri", e().modal.transformation.effectiveRadius(),
               a().modal.transformation.effectiveRadius(), kTolerance);
        number("afc", e().modal.adaptiveFeed ? 1 : 0, a().modal.adaptiveFeed ? 1 : 0);
    }

    void mGroups(int first, bool useMachine) {
        const MachineAuxState* em = useMachine ? e_.machine : nullptr;
        const MachineAuxState* am = useMachine ? a_.machine : nullptr;
        for (int group = first; group <= 15; ++group) {
            const auto m = static_cast<std::size_t>(group);
            number("m" + std::to_string(group), em ? em->mGroups[m] : e().mGroups[m],
                   am ? am->mGroups[m] : a().mGroups[m]);
        }
    }

    void spindles(bool useMachine) {
        const MachineAuxState* em = useMachine ? e_.machine : nullptr;
        const MachineAuxState* am = useMachine ? a_.machine : nullptr;
        for (int s = 1; s < kSpindleSlots; ++s) {
            const auto i = static_cast<std::size_t>(s);
            const std::string n = std::to_string(s);
            // A spindle the target needs in rotary axis mode has no speed to re-establish.
            if (!useMachine || e().modal.rotaryAxisMode[i] == 0)
                number("s" + n, em ? em->spindleSpeed[i] : e().modal.spindleSpeed[i],
                       am ? am->spindleSpeed[i] : a().modal.spindleSpeed[i], kTolerance);
            number("s_limit" + n, e().modal.spindleLimit[i], a().modal.spindleLimit[i], kTolerance);
            number("rotary_axis_mode" + n, e().modal.rotaryAxisMode[i],
                   a().modal.rotaryAxisMode[i]);
        }
    }

    void tools() {
        number("t", e().modal.tool, a().modal.tool);
        number("e", e().modal.edge, a().modal.edge);
        number("d", e().modal.correction, a().modal.correction);
        for (int t = 0; t < kToolSpindles; ++t)
            number("tool_spindle" + std::to_string(t + 1),
                   e().modal.toolSpindle[static_cast<std::size_t>(t)],
                   a().modal.toolSpindle[static_cast<std::size_t>(t)]);
        number("spc", e().modal.referenceSpindle, a().modal.referenceSpindle);
    }

    void positions(bool onlyWhereItMatters) {
        for (int axis = 0; axis < axes_.count(); ++axis) {
            const AxisModel& model = axes_.axis(axis);
            if (model.spindle && !model.rotary) continue;  // a plain spindle has no position
            const auto i = static_cast<std::size_t>(axis);
            // A spindle in spindle mode turns: its angle is not re-established.
            if (onlyWhereItMatters && model.spindle &&
                e().modal.rotaryAxisMode[static_cast<std::size_t>(model.spindleIndex)] == 0)
                continue;
            number("position." + model.displayName(), e().modal.machine[i], a().modal.machine[i],
                   kTolerance);
        }
    }

    /// The axes themselves (tool compensation applied), where both sides know them.
    void axisPositions() {
        if (!e_.axes || !a_.axes) return;
        for (int axis = 0; axis < axes_.count(); ++axis) {
            const AxisModel& model = axes_.axis(axis);
            if (model.spindle) continue;  // positions() covers the spindles' angles
            const auto i = static_cast<std::size_t>(axis);
            number("axis." + model.displayName(), (*e_.axes)[i], (*a_.axes)[i], kTolerance);
        }
    }

    void variables() {
        for (int v = 0; v < kVariableCount; ++v) {
            const auto i = static_cast<std::size_t>(v);
            if (!e().variables.written.test(i) && !a().variables.written.test(i)) continue;
            number("@" + std::to_string(v), e().variables.values[i], a().variables.values[i]);
        }
    }

    void buffers() {
        if (e_.m16Buffer && a_.m16Buffer)
            text("page61.m16", bufferText(*e_.m16Buffer), bufferText(*a_.m16Buffer));
        if (e_.qBuffer && a_.qBuffer)
            text("page61.q", bufferText(*e_.qBuffer), bufferText(*a_.qBuffer));
    }

    void callStack() {
        text("call_stack", stackText(e()), stackText(a()));
        const int selectedE = e().selected ? e().selected->number : -1;
        const int selectedA = a().selected ? a().selected->number : -1;
        number("selected_program", selectedE, selectedA);
    }

    const InterpreterState& e() const { return *e_.nc; }
    const InterpreterState& a() const { return *a_.nc; }
    std::vector<StateDifference> take() { return std::move(out_); }

  private:
    const RestartStateView& e_;
    const RestartStateView& a_;
    const ProcessAxes& axes_;
    std::vector<StateDifference> out_;
};

}  // namespace

std::vector<StateDifference> compareRestartStates(const RestartStateView& expected,
                                                  const RestartStateView& actual,
                                                  CompareScope scope, const ProcessAxes& axes) {
    if (!expected.nc || !actual.nc) return {};
    Comparison c(expected, actual, axes);
    c.gGroups();
    if (scope == CompareScope::Computed) {
        c.mGroups(1, false);
        c.number("m16", c.e().mGroups[16], c.a().mGroups[16]);
        c.number("q", c.e().lastQ, c.a().lastQ);
        c.spindles(false);
        c.tools();
        c.number("f", c.e().modal.feed, c.a().modal.feed, kTolerance);
        c.buffers();
        c.variables();
        c.positions(false);
        c.callStack();
    } else {
        c.mGroups(2, true);
        c.spindles(true);
        c.tools();
        c.number("f", c.e().modal.feed, c.a().modal.feed, kTolerance);
        c.positions(true);
        c.axisPositions();
    }
    return c.take();
}

std::string describeStateItem(const std::string& what) {
    if (what.empty()) return what;
    const auto after = [&](std::size_t n) { return what.substr(n); };
    if (what.size() > 1 && what[0] == 'g' && std::isdigit(static_cast<unsigned char>(what[1]))) {
        const int group = std::atoi(what.c_str() + 1);
        const std::string name = gGroupName(group).full;
        return "G group " + std::to_string(group) + (name.empty() ? "" : " (" + name + ")");
    }
    if (what.size() > 1 && what[0] == 'm' && std::isdigit(static_cast<unsigned char>(what[1])))
        return what == "m16" ? "M(16), last output" : "M group " + after(1);
    if (what.rfind("s_limit", 0) == 0) return "S" + after(7) + " limit (G92)";
    if (what.size() > 1 && what[0] == 's' && std::isdigit(static_cast<unsigned char>(what[1])))
        return "S" + after(1) + " speed";
    if (what.rfind("rotary_axis_mode", 0) == 0)
        return "rotary axis mode of S" + after(16) + " (page 60)";
    if (what.rfind("tool_spindle", 0) == 0) return "tool in tool spindle " + after(12);
    if (what.rfind("position.", 0) == 0) return "position of " + after(9);
    if (what.rfind("axis.", 0) == 0) return "axis " + after(5) + " (tool compensation applied)";
    if (what.rfind("plane.", 0) == 0) return "axis definition of " + after(6) + " (plane)";
    if (what[0] == '@') return "variable " + what;
    if (what == "q") return "Q, last output";
    if (what == "t") return "T (tool)";
    if (what == "e") return "E (edge)";
    if (what == "d") return "D (correction)";
    if (what == "f") return "F (feed)";
    if (what == "ri") return "RI (effective radius)";
    if (what == "afc") return "adaptive feed control (G26)";
    if (what == "spc") return "reference spindle (SPC)";
    if (what == "page61.m16") return "page 61 M(16) buffer";
    if (what == "page61.q") return "page 61 Q buffer";
    if (what == "call_stack") return "call stack";
    if (what == "selected_program") return "selected program";
    return what;
}

}  // namespace mtc::core
