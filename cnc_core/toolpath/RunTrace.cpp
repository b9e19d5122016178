#include "cnc_core/toolpath/RunTrace.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/motion/QueueFollower.h"
#include "cnc_core/motion/TrajectoryEngine.h"

namespace mtc::core {

namespace {
ToolpathSettings traceSettings() {
    ToolpathSettings settings;  // the view's default tolerance: the trace lies on its path
    settings.segmentLimit = RunTrace::kSegmentLimit;
    return settings;
}
}  // namespace

RunTrace::RunTrace(const ProcessAxes& axes) : builder_(axes, traceSettings()) {}

void RunTrace::begin(int program) {
    program_ = program;
    builder_.take();  // releases the last run's memory
    pending_.clear();
    done_ = 0;
    share_ = 0.0;
    moving_ = false;
    cut_ = truncated_ = false;
    ++run_;
    ++revision_;
}

void RunTrace::sent(const Motion& motion, bool queued) {
    if (cut_ || truncated_) return;
    const std::size_t index = builder_.geometry().moves.size();
    builder_.motion(motion);
    truncated_ = builder_.geometry().truncated;
    if (queued) pending_.push_back(index);
    ++revision_;
}

void RunTrace::follow(const motion::TrajectoryEngine& engine) {
    if (cut_) return;
    // A move without length never was queued, so it is not pending either.
    const std::optional<double> travelled =
        motion::followMachineQueue(engine, pending_, [](std::size_t) {});
    const std::size_t done = pending_.empty() ? builder_.geometry().moves.size() : pending_.front();
    const bool moving = travelled.has_value();
    const double share = travelled.value_or(0.0);
    if (done == done_ && moving == moving_ && share == share_) return;
    done_ = done;
    moving_ = moving;
    share_ = share;
    ++revision_;
}

void RunTrace::cut() {
    cut_ = true;
    pending_.clear();
    ++revision_;
}

long RunTrace::currentMove() const {
    if (moving_) return static_cast<long>(done_);
    return static_cast<long>(done_) - 1;
}

TracedExtent RunTrace::extent(bool developed) const {
    const ToolpathGeometry& g = builder_.geometry();
    const ToolpathLayer& layer = developed ? g.developed : g.scene;
    const auto first = [&](std::size_t move) {
        if (move >= g.moves.size()) return static_cast<std::uint32_t>(layer.segmentCount());
        return developed ? g.moves[move].firstDeveloped : g.moves[move].firstScene;
    };
    TracedExtent extent;
    extent.segments = first(done_);
    if (!moving_ || !(share_ > 0.0)) return extent;
    // The move the axes are on: its segments follow its path evenly (one
    // chord per line, chords of equal angle on an arc).
    const std::uint32_t count = first(done_ + 1) - extent.segments;
    const double at = share_ * count;
    const auto whole = std::min(count, static_cast<std::uint32_t>(std::floor(at)));
    extent.segments += whole;
    extent.share = whole < count ? at - whole : 0.0;
    return extent;
}

}  // namespace mtc::core
