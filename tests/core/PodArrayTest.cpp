#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

#include "cnc_core/support/PodArray.h"

namespace mtc::core {
namespace {

struct Pair {
    std::uint32_t key;
    std::uint32_t value;
};

PodArray<Pair> countingUpTo(std::uint32_t count) {
    PodArray<Pair> array;
    for (std::uint32_t i = 0; i < count; ++i)
        array.push_back({i, 3 * i});
    return array;
}

bool holdsCountingUpTo(const PodArray<Pair>& array, std::uint32_t count) {
    if (array.size() != count) return false;
    for (std::uint32_t i = 0; i < count; ++i)
        if (array[i].key != i || array[i].value != 3 * i) return false;
    return true;
}

TEST(PodArray, GrowingByAppendKeepsEveryElementInOrder) {
    const PodArray<Pair> array = countingUpTo(1000);
    EXPECT_TRUE(holdsCountingUpTo(array, 1000));
    EXPECT_GE(array.capacity(), array.size());
}

TEST(PodArray, EmplaceBackValueInitialisesTheNewElement) {
    PodArray<Pair> array;
    array.push_back({7, 8});
    array.clear();  // the slot still holds {7, 8}
    const Pair& fresh = array.emplace_back();
    EXPECT_EQ(fresh.key, 0u);
    EXPECT_EQ(fresh.value, 0u);
}

TEST(PodArray, SpareSlotsWrittenInPlaceAreAppendedByEndAt) {
    PodArray<Pair> array = countingUpTo(3);
    array.makeSpare();
    Pair* slot = array.spareBegin();
    std::uint32_t next = 3;
    while (slot != array.spareEnd() && next < 5) {
        *slot++ = {next, 3 * next};
        ++next;
    }
    array.endAt(slot);
    EXPECT_TRUE(holdsCountingUpTo(array, next));
    EXPECT_GE(next, 4u);  // makeSpare gave room for at least one
}

TEST(PodArray, CopiesAreIndependentAndMovesLeaveTheSourceEmpty) {
    PodArray<Pair> original = countingUpTo(100);
    PodArray<Pair> copy = original;
    ASSERT_EQ(copy.size(), 100u);
    copy[0].value = 99;
    EXPECT_EQ(original[0].value, 0u);

    PodArray<Pair> assigned;
    assigned = original;
    EXPECT_TRUE(holdsCountingUpTo(assigned, 100));

    PodArray<Pair> moved = std::move(original);
    EXPECT_TRUE(holdsCountingUpTo(moved, 100));
    // The moved-from state is specified: empty, without memory.
    // NOLINTNEXTLINE(bugprone-use-after-move,clang-analyzer-cplusplus.Move)
    EXPECT_EQ(original.capacity() + original.size(), 0u);

    copy = std::move(moved);
    EXPECT_TRUE(holdsCountingUpTo(copy, 100));
}

TEST(PodArray, ResizeShrinksOrFillsWithValueInitialisedElements) {
    PodArray<Pair> array = countingUpTo(10);
    array.resize(4);
    EXPECT_TRUE(holdsCountingUpTo(array, 4));
    array.resize(6);
    ASSERT_EQ(array.size(), 6u);
    EXPECT_EQ(array[5].key, 0u);
    EXPECT_EQ(array[5].value, 0u);
}

TEST(PodArray, ReserveAndShrinkToFitKeepTheContents) {
    PodArray<Pair> array = countingUpTo(10);
    array.reserve(500);
    EXPECT_GE(array.capacity(), 500u);
    EXPECT_TRUE(holdsCountingUpTo(array, 10));
    array.shrink_to_fit();
    EXPECT_EQ(array.capacity(), 10u);
    EXPECT_TRUE(holdsCountingUpTo(array, 10));
}

TEST(PodArray, ArraysPastTheLargeArraySizeKeepTheirContentsThroughGrowth) {
    // 8-byte elements: the array crosses kLargeArrayBytes (huge-page memory)
    // while it grows, and the copy and shrink go through that memory too.
    const auto count = static_cast<std::uint32_t>(kLargeArrayBytes / sizeof(Pair) + 1000);
    PodArray<Pair> array = countingUpTo(count);
    EXPECT_TRUE(holdsCountingUpTo(array, count));
    array.shrink_to_fit();
    const PodArray<Pair> copy = array;
    EXPECT_TRUE(holdsCountingUpTo(copy, count));
}

TEST(PodArray, LargeArraysStartOnAHugePageBoundary) {
    // Only the last partial 2 MiB stretch of a large array takes small pages.
    PodArray<Pair> array;
    array.reserve(kLargeArrayBytes / sizeof(Pair));
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(array.data()) % (std::uintptr_t{2} << 20), 0u);
}

}  // namespace
}  // namespace mtc::core
