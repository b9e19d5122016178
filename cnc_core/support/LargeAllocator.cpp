#include "cnc_core/support/LargeAllocator.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace mtc::core {

// From malloc, so that the array stays visible to malloc's statistics (the
// parse benchmark reports them) and costs no more address space than asked.
// malloc gives an array this large its own mapping; the kernel backs every
// 2 MiB-aligned stretch of a range marked MADV_HUGEPAGE with one huge page,
// and the pages at either end that are not a whole stretch with small pages.
void* allocateLargeArray(std::size_t bytes) {
    void* memory = std::malloc(bytes);
    if (!memory) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kPage = 4096;  // madvise takes whole pages
    const auto begin = (reinterpret_cast<std::uintptr_t>(memory) + kPage - 1) & ~(kPage - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(memory) + bytes) & ~(kPage - 1);
    if (end > begin)  // a hint: without huge pages all works as before
        ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
    return memory;
}

void releaseLargeArray(void* memory, std::size_t /*bytes*/) {
    std::free(memory);
}

}  // namespace mtc::core
