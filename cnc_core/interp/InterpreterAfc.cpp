// Interpreter and adaptive feed control (seed 002): G25/G26, ITM, AXD
// P-7-3651, the functions that exclude G26, and the runtime errors the
// simulated machine raises while it moves (508, 509, 510).
#include <vector>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/interp/MotionPath.h"

namespace mtc::core {
namespace {

/// G functions of the block (and modal ones in force after it) that cannot
/// run together with adaptive feed control.
std::vector<int> excludingFunctions(const BlockInput& in, const ModalState& next) {
    std::vector<int> functions;
    if (in.axisFunction != 0) functions.push_back(in.axisFunction);
    const int transformation = next.g[kGroupTransformation];
    if (transformation == 31 || transformation == 32) functions.push_back(transformation);
    return functions;
}

}  // namespace

void Interpreter::setAdaptiveFeed(std::shared_ptr<AdaptiveFeedControl> afc) {
    afc_ = std::move(afc);
    evaluator_.setAdaptiveFeed(afc_.get());
}

bool Interpreter::adaptiveFeedInvolved() const {
    return input_.adaptiveFeed != 0 || input_.idleMeasurement || input_.stallRecording ||
           (afc_ && afc_->active());
}

bool Interpreter::planAdaptiveFeed(const BlockContext& context) {
    const BlockInput& in = input_;
    if (in.adaptiveFeed != 0) plan_.next.adaptiveFeed = in.adaptiveFeed == 26;
    if (!afc_ && options_.logicalAdaptiveFeed && config_.flag("B062"))
        return true;  // the computing process: nothing moves, nothing is measured
    if (!afc_ && (in.adaptiveFeed == 26 || in.idleMeasurement || in.stallRecording))
        return context.error("AFC_NOT_AVAILABLE",
                             "this process has no adaptive feed control (G26, ITM, AXD P-7-3651)",
                             in.adaptiveFeed == 26 ? in.adaptiveFeedColumn : in.idleColumn);
    if (!afc_) return true;  // G25 alone: the switch-on state
    const std::vector<int> excluded = excludingFunctions(in, plan_.next);
    std::string reason;
    if (in.adaptiveFeed == 26) {
        const AfcStatus status = afc_->checkSwitchOn(excluded, reason);
        if (status != AfcStatus::Ok)
            return context.error(afcStatusCode(status), reason, in.adaptiveFeedColumn);
    } else if (afc_->active() && in.adaptiveFeed != 25 && !excluded.empty()) {
        return context.error("AFC_INCOMPATIBLE",
                             std::string(AdaptiveFeedControl::incompatibleFunction(excluded[0])) +
                                 " is not possible while adaptive feed control (G26) is "
                                 "active; switch it off with G25 first");
    }
    if (in.idleMeasurement && !afc_->available())
        return context.error("AFC_NOT_AVAILABLE",
                             "ITM: adaptive feed control is not available (Bxx.062 = no)",
                             in.idleColumn);
    if (in.idleMeasurement && !plan_.hasMotion)
        return context.error("AFC_ERROR_508",
                             "error 508: idling torque recording needs a move in the ITM block "
                             "(the block has no execution time)",
                             in.idleColumn);
    if (in.stallRecording) {
        if (!(in.stallPeriodMs >= 0.0 && in.stallPeriodMs <= 60000.0))
            return context.error("AFC_BAD_PERIOD",
                                 "P-7-3651: the period must be 0.0 ... 60000 ms, got " +
                                     std::to_string(in.stallPeriodMs),
                                 in.stallColumn);
        const std::string axis(in.stallAxis.data());
        if (!config_.axis(axis))
            return context.error("AXIS_UNKNOWN", "AXD: this process has no axis " + axis,
                                 in.stallColumn);
    }
    return true;
}

void Interpreter::commitAdaptiveFeed() {
    const BlockInput& in = input_;
    if (!afc_) return;
    if (in.adaptiveFeed == 25) afc_->switchOff();
    if (in.adaptiveFeed == 26) afc_->switchOn(excludingFunctions(in, state_.modal));
    if (in.stallRecording)
        afc_->recordStallTorque(std::string(in.stallAxis.data()), in.stallPeriodMs);
    afc_->requestIdleMeasurement(in.idleMeasurement && plan_.hasMotion && options_.output.motion);
}

bool Interpreter::adaptiveFeedAfterMotion(const Program& program, DiagnosticList& diagnostics) {
    if (!afc_) return true;
    afc_->requestIdleMeasurement(false);  // a sink that is no machine did not measure
    const double extra = afc_->takeExtraSeconds();
    if (extra != 0.0) {
        state_.modal.time += extra;
        modalChanged();
    }
    std::string message;
    const double reached = afc_->stopFraction();
    afc_->setStopFraction(1.0);
    const AfcStatus status = afc_->takeRuntimeError(message);
    if (status == AfcStatus::Ok) return true;
    // AFC-012: the axes stand where the machine stopped them, on the path of
    // the block's move; the state (and the final position) says so too.
    if (reached < 1.0 && options_.output.motion)
        takeMachinePositions(motionPointAt(motion_, reached));
    const SourceLocation where = sinkLocation(program, state_.block);
    diagnostics.error(afcStatusCode(status), where, message);
    return false;
}

}  // namespace mtc::core
