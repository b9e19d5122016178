#include "cnc_core/support/LargeAllocator.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace mtc::core {

namespace {

/// The size of a transparent huge page (x86-64, AArch64 with 4 KiB pages).
constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

}  // namespace

// From malloc, so that the array stays visible to malloc's statistics (the
// parse benchmark reports them). The kernel backs every 2 MiB-aligned
// stretch of a range marked MADV_HUGEPAGE with one huge page and the rest
// with small pages; the array starts on such a stretch, so that only its
// last, partial stretch takes small pages (from any malloc address, the
// first one did as well: up to 2 MiB of small pages more per array, each a
// page fault of its own when the parser first writes it).
void* allocateLargeArray(std::size_t bytes) {
    void* memory = nullptr;
    if (::posix_memalign(&memory, kHugePageBytes, bytes) != 0 || memory == nullptr)
        throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
    constexpr std::size_t kPage = 4096;  // madvise takes whole pages
    const std::size_t whole = bytes & ~(kPage - 1);
    if (whole > 0)  // a hint: without huge pages all works as before
        ::madvise(memory, whole, MADV_HUGEPAGE);
#endif
    return memory;
}

void releaseLargeArray(void* memory, std::size_t /*bytes*/) {
    std::free(memory);
}

}  // namespace mtc::core
