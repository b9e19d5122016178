#include "cli/RestartRecorder.h"

namespace mtc::cli {

std::string RestartRecorder::phaseName() const {
    if (sequence_ == nullptr) return "none";
    switch (sequence_->phase()) {
        case core::RestartPhase::Computing:
            return "computing";
        case core::RestartPhase::Adjusting:
            return "adjust";
        case core::RestartPhase::Repositioning:
            return "repos";
        default:
            return core::restartPhaseName(sequence_->phase());
    }
}

void RestartRecorder::motion(const core::Motion& motion) {
    if (sequence_ == nullptr) return;
    if (sequence_->phase() == core::RestartPhase::Adjusting) adjustMotion_.push_back(motion);
    if (sequence_->phase() == core::RestartPhase::Repositioning) reposMotion_.push_back(motion);
}

void RestartRecorder::auxiliary(const core::AuxOutput& output) {
    aux_.push_back({output, phaseName()});
}

}  // namespace mtc::cli
