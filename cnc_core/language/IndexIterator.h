#pragma once

#include <cstddef>
#include <iterator>

namespace mtc::core {

/// Input iterator over a packed list that hands out elements by value
/// (`list[index]` unpacks them), shared by WordList and BlockList.
template <typename List, typename Value>
class IndexIterator {
  public:
    using value_type = Value;
    using difference_type = std::ptrdiff_t;
    using reference = const Value;
    using pointer = void;
    using iterator_category = std::input_iterator_tag;
    IndexIterator(const List* list, std::size_t index) : list_(list), index_(index) {}
    const Value operator*() const { return (*list_)[index_]; }
    IndexIterator& operator++() {
        ++index_;
        return *this;
    }
    bool operator==(const IndexIterator& other) const { return index_ == other.index_; }
    bool operator!=(const IndexIterator& other) const { return index_ != other.index_; }

  private:
    const List* list_;
    std::size_t index_;
};

}  // namespace mtc::core
