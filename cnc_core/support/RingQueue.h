#pragma once

#include <cstddef>
#include <iterator>
#include <type_traits>
#include <utility>
#include <vector>

namespace mtc::core {

/// A first-in first-out queue in one growing array used as a ring: pushing
/// at the back and dropping at the front move no other element and allocate
/// only when the queue outgrows every size it had before. std::deque
/// allocates a node per element once an element is 512 bytes or more (the
/// station's queued block states, the trend's records), which cost a
/// malloc/free pair per block of a headless run.
/// `T` must be default-constructible and move-assignable. A dropped slot of
/// a type with a destructor is handed to `Release` so that it gives up what
/// it holds (shared programs); a trivial one is reset when it is reused.
/// Every element emplace_back() returns of a non-trivial type is a T() or
/// what `Release` left of a dropped one: the caller assigns every field.
/// The default way a dropped element gives up what it holds: it becomes T().
struct ResetToDefault {
    template <typename T>
    void operator()(T& element) const {
        element = T();
    }
};

template <typename T, typename Release = ResetToDefault>
class RingQueue {
    template <typename Queue, typename Element>
    class Iterator;

  public:
    using iterator = Iterator<RingQueue, T>;
    using const_iterator = Iterator<const RingQueue, const T>;

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    /// Slots held (elements and dropped ones kept for reuse).
    std::size_t capacity() const { return slots_.size(); }

    /// Element `i`, 0 = the oldest (front).
    T& operator[](std::size_t i) { return slots_[slot(i)]; }
    const T& operator[](std::size_t i) const { return slots_[slot(i)]; }
    T& front() { return slots_[head_]; }
    const T& front() const { return slots_[head_]; }
    T& back() { return (*this)[size_ - 1]; }
    const T& back() const { return (*this)[size_ - 1]; }

    /// Random-access iterators from the oldest element to past the newest
    /// (std::upper_bound, range loops). Pushing or dropping invalidates them.
    iterator begin() { return {this, 0}; }
    iterator end() { return {this, size_}; }
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size_}; }

    void push_back(const T& value) { emplace_back_for_overwrite() = value; }
    void push_back(T&& value) { emplace_back_for_overwrite() = std::move(value); }
    /// Appends a default element and returns it, to be filled in place
    /// (large elements are then written once instead of copied twice).
    T& emplace_back() {
        T& slot = emplace_back_for_overwrite();
        if constexpr (std::is_trivially_destructible_v<T>) slot = T();  // else reset when dropped
        return slot;
    }
    /// Appends an element and returns it as its slot's last use left it (a
    /// trivial type is not reset): the caller assigns the whole element.
    T& emplace_back_for_overwrite() {
        if (size_ == slots_.size()) grow();
        T& slot = slots_[this->slot(size_)];
        ++size_;
        return slot;
    }
    /// Drops the oldest element (the queue must not be empty).
    void pop_front() { dropFront(1); }
    /// Drops the `count` oldest elements (at most size()).
    void dropFront(std::size_t count) {
        if (count > size_) count = size_;
        if constexpr (!std::is_trivially_destructible_v<T>) {
            for (std::size_t i = 0; i < count; ++i)
                Release{}(slots_[slot(i)]);
        }
        head_ = (head_ + count) & mask();
        size_ -= count;
    }
    /// Drops every element; the array is kept for the next pushes.
    void clear() { dropFront(size_); }

  private:
    std::size_t mask() const { return slots_.size() - 1; }
    std::size_t slot(std::size_t i) const { return (head_ + i) & mask(); }
    /// Doubles the array (a power of two, so a slot is a mask, not a
    /// division) and moves the elements to its start in queue order.
    void grow() {
        std::vector<T> bigger(slots_.empty() ? 16 : slots_.size() * 2);
        for (std::size_t i = 0; i < size_; ++i)
            bigger[i] = std::move(slots_[slot(i)]);
        slots_ = std::move(bigger);
        head_ = 0;
    }

    std::vector<T> slots_;
    std::size_t head_ = 0;
    std::size_t size_ = 0;
};

/// A position in the queue (0 = front), valid until the next push or drop.
template <typename T, typename Release>
template <typename Queue, typename Element>
class RingQueue<T, Release>::Iterator {
  public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = std::remove_const_t<Element>;
    using difference_type = std::ptrdiff_t;
    using pointer = Element*;
    using reference = Element&;

    Iterator() = default;
    Iterator(Queue* queue, std::size_t index) : queue_(queue), index_(index) {}

    reference operator*() const { return (*queue_)[index_]; }
    pointer operator->() const { return &(*queue_)[index_]; }
    reference operator[](difference_type n) const { return *(*this + n); }
    Iterator& operator++() { return *this += 1; }
    Iterator operator++(int) {
        Iterator before = *this;
        ++*this;
        return before;
    }
    Iterator& operator--() { return *this -= 1; }
    Iterator operator--(int) {
        Iterator before = *this;
        --*this;
        return before;
    }
    Iterator& operator+=(difference_type n) {
        index_ = static_cast<std::size_t>(static_cast<difference_type>(index_) + n);
        return *this;
    }
    Iterator& operator-=(difference_type n) { return *this += -n; }
    friend Iterator operator+(Iterator it, difference_type n) { return it += n; }
    friend Iterator operator+(difference_type n, Iterator it) { return it += n; }
    friend Iterator operator-(Iterator it, difference_type n) { return it -= n; }
    friend difference_type operator-(const Iterator& a, const Iterator& b) {
        return static_cast<difference_type>(a.index_) - static_cast<difference_type>(b.index_);
    }
    friend bool operator==(const Iterator& a, const Iterator& b) { return a.index_ == b.index_; }
    friend bool operator!=(const Iterator& a, const Iterator& b) { return a.index_ != b.index_; }
    friend bool operator<(const Iterator& a, const Iterator& b) { return a.index_ < b.index_; }
    friend bool operator>(const Iterator& a, const Iterator& b) { return b < a; }
    friend bool operator<=(const Iterator& a, const Iterator& b) { return !(b < a); }
    friend bool operator>=(const Iterator& a, const Iterator& b) { return !(a < b); }

  private:
    Queue* queue_ = nullptr;
    std::size_t index_ = 0;
};

}  // namespace mtc::core
