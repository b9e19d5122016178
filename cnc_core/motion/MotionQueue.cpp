#include "cnc_core/motion/MotionQueue.h"

#include <algorithm>

namespace mtc::core::motion {

MotionQueue::MotionQueue(std::size_t capacity)
    : storage_(std::max<std::size_t>(capacity, 1) + 8),
      slots_(storage_.size()),
      capacity_(std::max<std::size_t>(capacity, 1)) {}

void MotionQueue::grow() {
    regrow(storage_.size() * 2);
}

void MotionQueue::reserve(std::size_t items) {
    if (items > storage_.size()) regrow(items);
}

void MotionQueue::regrow(std::size_t slots) {
    std::vector<QueueItem> grown(slots);
    for (std::size_t i = 0; i < size_; ++i)
        grown[i] = std::move(at(i));
    storage_ = std::move(grown);
    slots_ = storage_.size();
    head_ = 0;
}

QueueItem& MotionQueue::pushBack() {
    QueueItem& item = nextSlot();
    ++size_;
    ++pushed_;
    return item;
}

void MotionQueue::popFront() {
    if (size_ == 0) return;
    storage_[head_].course.reset();  // slots are reused: let the course go now
    head_ = slot(1);
    --size_;
    ++popped_;
}

const QueueItem* MotionQueue::moveBeforeEnd() const {
    for (std::size_t i = size_; i-- > 0;) {
        const QueueItem& item = at(i);
        if (item.kind == QueueItem::Kind::Move) return &item;
        if (item.kind != QueueItem::Kind::Action || item.action.stopsPath) return nullptr;
    }
    return nullptr;
}

}  // namespace mtc::core::motion
