#pragma once

#include <array>

namespace mtc::core {

/// One of the two auxiliary function buffers of machine data page 61 (seed
/// 000, 4.2): the last 40 M functions of group 16, or the last 40 Q functions,
/// collected during the computing process. When the 41st function arrives the
/// oldest is dropped and the others move one place down, so the newest is
/// always the last stored entry. Plain data, no allocation.
class FunctionBuffer {
  public:
    static constexpr int kLength = 40;

    /// Empties the buffer (every element reads 0 again).
    void clear() {
        first_ = 0;
        count_ = 0;
    }
    /// Stores `value` as the newest entry; drops the oldest when 40 are stored.
    void push(int value) {
        if (count_ < kLength) {
            ring_[static_cast<std::size_t>((first_ + count_++) % kLength)] = value;
            return;
        }
        ring_[static_cast<std::size_t>(first_)] = value;
        first_ = first_ + 1 == kLength ? 0 : first_ + 1;  // once full, every push comes here
    }
    /// Number of stored entries (0..40).
    int size() const { return count_; }
    /// The page 61 elements 1..40 as stored: oldest first, 0 after the last entry.
    std::array<int, kLength> elements() const {
        std::array<int, kLength> out{};
        for (int i = 0; i < count_; ++i)
            out[static_cast<std::size_t>(i)] =
                ring_[static_cast<std::size_t>((first_ + i) % kLength)];
        return out;
    }

  private:
    std::array<int, kLength> ring_{};
    int first_ = 0;  ///< index of the oldest entry
    int count_ = 0;
};

}  // namespace mtc::core
