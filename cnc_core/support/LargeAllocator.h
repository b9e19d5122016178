#pragma once

#include <cstddef>
#include <new>

namespace mtc::core {

/// Memory for one large array of `bytes`, from malloc and marked for
/// transparent huge pages where the system has them (Linux madvise).
/// Throws std::bad_alloc. Free with releaseLargeArray(p, bytes).
void* allocateLargeArray(std::size_t bytes);
void releaseLargeArray(void* memory, std::size_t bytes);

/// Arrays from this size on take allocateLargeArray.
constexpr std::size_t kLargeArrayBytes = std::size_t{4} << 20;

/// Allocator of the packed arrays of a parsed program (WordList, BlockList).
/// A parse fills tens of megabytes of fresh memory in one go; with 4 KiB
/// pages that is one page fault per 4 KiB, which took about a fifth of the
/// parse of a 1,000,000-block program. Arrays of kLargeArrayBytes and more
/// are asked for in huge pages (one fault per 2 MiB); smaller ones come from
/// operator new as with std::allocator.
template <typename T>
struct LargeAllocator {
    using value_type = T;
    LargeAllocator() = default;
    template <typename U>
    LargeAllocator(const LargeAllocator<U>& /*other*/) {}

    T* allocate(std::size_t count) {
        if (count > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = count * sizeof(T);
        if (bytes < kLargeArrayBytes) return static_cast<T*>(::operator new(bytes));
        return static_cast<T*>(allocateLargeArray(bytes));
    }
    void deallocate(T* memory, std::size_t count) {
        const std::size_t bytes = count * sizeof(T);
        if (bytes < kLargeArrayBytes)
            ::operator delete(memory);
        else
            releaseLargeArray(memory, bytes);
    }
};

template <typename T, typename U>
bool operator==(const LargeAllocator<T>& /*a*/, const LargeAllocator<U>& /*b*/) {
    return true;
}
template <typename T, typename U>
bool operator!=(const LargeAllocator<T>& /*a*/, const LargeAllocator<U>& /*b*/) {
    return false;
}

}  // namespace mtc::core
