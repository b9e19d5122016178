#include "screens/toolpath/ToolpathFramePacer.h"

#include <algorithm>

namespace mtc::screens {

ToolpathFramePacer::ToolpathFramePacer(std::function<void()> draw, QObject* parent)
    : QObject(parent), draw_(std::move(draw)) {
    timer_.setSingleShot(true);
    connect(&timer_, &QTimer::timeout, this, [this] { draw_(); });
}

void ToolpathFramePacer::request() {
    if (!timer_.isActive()) schedule();
}

void ToolpathFramePacer::schedule() {
    const qint64 since = last_.isValid() ? last_.elapsed() : interval_;
    timer_.start(static_cast<int>(std::max<qint64>(0, interval_ - since)));
}

void ToolpathFramePacer::drawn() {
    timer_.stop();  // this frame shows what the waiting one would have shown
    last_.start();
}

void ToolpathFramePacer::setInterval(int milliseconds) {
    interval_ = std::max(0, milliseconds);
    if (timer_.isActive()) schedule();
}

}  // namespace mtc::screens
