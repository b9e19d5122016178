#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cnc_core/afc/AfcObservedMove.h"
#include "cnc_core/afc/AfcTrendSample.h"
#include "cnc_core/support/RingQueue.h"

namespace mtc::core {

/// Bounded trend of the last `capacity` samples, filled by the simulated
/// machine while feed moves run: the oldest samples are dropped when it is
/// full. A move without G26 is kept as one AfcObservedMove whose samples are
/// made when read; the controller's samples are kept as they are. The trend
/// screen reads it by index.
class AfcTrendRecorder {
  public:
    /// Keeps at most `capacity` samples (at least 2).
    explicit AfcTrendRecorder(std::size_t capacity = 20000);

    /// Appends a sample (drops the oldest when full).
    void add(const AfcTrendSample& sample);
    /// Appends the move's samples 1 .. move.count (at least one).
    void add(const AfcObservedMove& move);
    /// Adds an observed move that `fill(AfcObservedMove&)` writes in place
    /// (every field; one per feed move of a run, so it is not built and copied).
    template <typename Fill>
    void addObserved(Fill fill) {
        Entry& entry = entries_.emplace_back_for_overwrite();
        fill(entry.move);
        entry.observed = true;  // entry.first: keep()
        entry.move.count = std::max(1, entry.move.count);
        keep(entry);
    }
    /// Number of samples kept.
    std::size_t size() const { return count_; }
    std::size_t capacity() const { return capacity_; }
    /// Sample `index`, 0 = the oldest kept (the newest when index >= size();
    /// a default sample when empty).
    AfcTrendSample at(std::size_t index) const;
    /// Every kept sample, oldest first.
    std::vector<AfcTrendSample> samples() const;
    /// Counts every add() and clear() (screens repaint when it moves).
    std::uint64_t revision() const { return revision_; }
    /// Forgets every sample.
    void clear();
    /// The samples as CSV with a header line (C locale numbers, '.' decimal).
    std::string csv() const;

  private:
    /// Samples added one at a time are a move of one sample whose constant
    /// is the sample itself.
    struct Entry {
        AfcObservedMove move;
        bool observed = false;
        std::uint64_t first = 0;  ///< number of samples added before it
        AfcTrendSample sample(int k) const { return observed ? move.sample(k) : move.constant; }
    };
    /// Counts the new back entry's samples and drops the oldest beyond the capacity.
    void keep(Entry& entry);
    /// Calls `visit` with every kept sample, oldest first.
    template <typename Visit>
    void forEach(Visit visit) const;

    std::size_t capacity_;
    RingQueue<Entry> entries_;
    int skipped_ = 0;  ///< samples of entries_.front() already dropped
    std::size_t count_ = 0;
    std::uint64_t added_ = 0;  ///< samples added since the last clear()
    std::uint64_t revision_ = 0;
};

}  // namespace mtc::core
