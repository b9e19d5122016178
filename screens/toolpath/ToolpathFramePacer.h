#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <functional>

namespace mtc::screens {

/// Paces the toolpath view's frames (TP-029): a request draws in the next
/// event-loop pass, but not sooner than one frame interval after the start
/// of the frame before. While a program runs the station changes at the
/// panel's tick (50 Hz) and every change asks for a frame; on llvmpipe a
/// frame of the whole window costs about as much as the tick leaves, so the
/// view drew as fast as the CPU allowed. Many requests within one interval
/// give one frame, drawn with what is newest then.
class ToolpathFramePacer : public QObject {
  public:
    /// Frames per second at most by default (the tool and backplot stay fluent).
    static constexpr int kDefaultIntervalMs = 40;

    /// `draw` renders a frame; it must call drawn() (renderNow does).
    ToolpathFramePacer(std::function<void()> draw, QObject* parent = nullptr);
    /// Something visible changed: a frame follows (requests coalesce).
    void request();
    /// A frame was drawn now, requested or not: the next waits an interval.
    void drawn();
    /// Least time from the start of one frame to the start of the next
    /// (0: one frame per event-loop pass). A waiting frame is rescheduled.
    void setInterval(int milliseconds);
    int interval() const { return interval_; }
    /// A frame is waiting for its time.
    bool pending() const { return timer_.isActive(); }

  private:
    void schedule();

    std::function<void()> draw_;
    QTimer timer_;
    QElapsedTimer last_;  ///< started when the last frame began
    int interval_ = kDefaultIntervalMs;
};

}  // namespace mtc::screens
