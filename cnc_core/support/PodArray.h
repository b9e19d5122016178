#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include "cnc_core/support/LargeAllocator.h"

namespace mtc::core {

/// A growable array of trivially copyable elements in LargeAllocator memory
/// (huge pages for large arrays), for the packed lists of a parsed program.
/// What std::vector does for them, except that the append in the parser's
/// hot loop stays small enough to be inlined: the growth is out of line.
template <typename T>
class PodArray {
    static_assert(std::is_trivially_copyable_v<T>);

  public:
    PodArray() = default;
    PodArray(const PodArray& other) { copyFrom(other); }
    PodArray(PodArray&& other) noexcept
        : data_(std::exchange(other.data_, nullptr)),
          size_(std::exchange(other.size_, 0)),
          capacity_(std::exchange(other.capacity_, 0)) {}
    PodArray& operator=(const PodArray& other) {
        if (this != &other) {
            PodArray copy(other);
            swap(copy);
        }
        return *this;
    }
    PodArray& operator=(PodArray&& other) noexcept {
        PodArray moved(std::move(other));
        swap(moved);
        return *this;
    }
    ~PodArray() {
        if (data_ != nullptr) LargeAllocator<T>().deallocate(data_, capacity_);
    }

    std::size_t size() const { return size_; }
    std::size_t capacity() const { return capacity_; }
    bool empty() const { return size_ == 0; }
    T* data() { return data_; }
    T& operator[](std::size_t index) { return data_[index]; }
    const T& operator[](std::size_t index) const { return data_[index]; }

    /// Appends a value-initialised element and returns it.
    T& emplace_back() {
        if (size_ == capacity_) grow();
        T& element = data_[size_++];
        element = T{};
        return element;
    }
    void push_back(const T& value) { emplace_back() = value; }
    /// In-place appending: the free slots after the last element are
    /// [spareBegin(), spareEnd()); after writing some, endAt(the slot after
    /// the last one written) appends them. makeSpare() makes room for one
    /// element when there is none (growing as emplace_back does).
    T* spareBegin() { return data_ + size_; }
    T* spareEnd() { return data_ + capacity_; }
    void endAt(const T* end) { size_ = static_cast<std::size_t>(end - data_); }
    void makeSpare() {
        if (size_ == capacity_) grow();
    }
    void reserve(std::size_t count) {
        if (count > capacity_) reallocate(count);
    }
    /// Shrinks to `count` elements or grows with value-initialised ones.
    void resize(std::size_t count) {
        reserve(count);
        for (std::size_t i = size_; i < count; ++i)
            data_[i] = T{};
        size_ = count;
    }
    void shrink_to_fit() {
        if (capacity_ > size_) reallocate(size_);
    }
    void clear() { size_ = 0; }
    void swap(PodArray& other) noexcept {
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(capacity_, other.capacity_);
    }

  private:
    void copyFrom(const PodArray& other) {
        reallocate(other.size_);
        if (other.size_ > 0) std::memcpy(data_, other.data_, other.size_ * sizeof(T));
        size_ = other.size_;
    }
    /// Doubles the capacity, as std::vector does.
    __attribute__((noinline)) void grow() {
        const std::size_t capacity = capacity_ == 0 ? 1 : 2 * capacity_;
        replaceStorage(LargeAllocator<T>().allocate(capacity), capacity);
    }
    /// Moves the elements to memory for `capacity` (>= size_) elements.
    void reallocate(std::size_t capacity) {
        replaceStorage(capacity > 0 ? LargeAllocator<T>().allocate(capacity) : nullptr, capacity);
    }
    /// Moves the elements (as many as fit) to `data` of `capacity` elements.
    void replaceStorage(T* data, std::size_t capacity) {
        if (capacity < size_) size_ = capacity;
        if (size_ > 0) std::memcpy(data, data_, size_ * sizeof(T));
        if (data_ != nullptr) LargeAllocator<T>().deallocate(data_, capacity_);
        data_ = data;
        capacity_ = capacity;
    }

    T* data_ = nullptr;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;
};

}  // namespace mtc::core
