#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

#include "cnc_core/support/RingQueue.h"

namespace mtc::core {
namespace {

std::string contents(const RingQueue<int>& queue) {
    std::string text;
    for (std::size_t i = 0; i < queue.size(); ++i)
        text += std::to_string(queue[i]) + " ";
    return text;
}

TEST(RingQueue, KeepsOrderWhenItWrapsAndGrowsWhileWrapped) {
    RingQueue<int> queue;
    for (int i = 0; i < 16; ++i)
        queue.push_back(i);
    queue.dropFront(10);  // head in the middle of the first 16 slots
    for (int i = 16; i < 26; ++i)
        queue.push_back(i);  // wraps, then grows while wrapped
    ASSERT_EQ(queue.size(), 16u);
    EXPECT_EQ(queue.front(), 10);
    EXPECT_EQ(queue.back(), 25);
    EXPECT_EQ(contents(queue), "10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 ");
    queue.pop_front();
    EXPECT_EQ(queue.front(), 11);
}

TEST(RingQueue, IteratorsWalkAWrappedQueueInOrderAndSearchIt) {
    RingQueue<int> queue;
    for (int i = 0; i < 16; ++i)
        queue.push_back(i * 10);
    queue.dropFront(12);
    for (int i = 16; i < 20; ++i)
        queue.push_back(i * 10);  // 120 .. 190, wrapped around the array's end
    std::string walked;
    for (int value : queue)
        walked += std::to_string(value) + " ";
    EXPECT_EQ(walked, "120 130 140 150 160 170 180 190 ");
    const RingQueue<int>& constQueue = queue;
    EXPECT_EQ(constQueue.end() - constQueue.begin(), 8);
    auto found = std::upper_bound(constQueue.begin(), constQueue.end(), 165);
    ASSERT_NE(found, constQueue.end());
    EXPECT_EQ(*found, 170);
    EXPECT_EQ(found - constQueue.begin(), 5);
    EXPECT_EQ(*std::prev(found), 160);
    EXPECT_EQ(std::upper_bound(constQueue.begin(), constQueue.end(), 500), constQueue.end());
    for (int& value : queue)
        value += 1;
    EXPECT_EQ(contents(queue), "121 131 141 151 161 171 181 191 ");
}

TEST(RingQueue, DropFrontStopsAtTheSizeAndClearKeepsWorking) {
    RingQueue<int> queue;
    queue.push_back(1);
    queue.push_back(2);
    queue.dropFront(5);
    EXPECT_TRUE(queue.empty());
    queue.push_back(3);
    EXPECT_EQ(contents(queue), "3 ");
    queue.clear();
    EXPECT_EQ(queue.size(), 0u);
    queue.push_back(4);
    EXPECT_EQ(contents(queue), "4 ");
}

TEST(RingQueue, ATrivialSlotComesBackAsADefaultElement) {
    struct Pair {
        int a = 7;
        int b = 8;
    };
    RingQueue<Pair> queue;
    for (int i = 0; i < 16; ++i)
        queue.emplace_back() = Pair{i, i};
    queue.dropFront(16);
    const Pair& reused = queue.emplace_back();  // the first slot again
    EXPECT_EQ(reused.a, 7);
    EXPECT_EQ(reused.b, 8);
}

TEST(RingQueue, ADroppedElementLetsGoOfWhatItHolds) {
    RingQueue<std::shared_ptr<int>> queue;
    auto shared = std::make_shared<int>(5);
    queue.push_back(shared);
    queue.push_back(shared);
    EXPECT_EQ(shared.use_count(), 3);
    queue.pop_front();
    EXPECT_EQ(shared.use_count(), 2);
    queue.clear();
    EXPECT_EQ(shared.use_count(), 1);
}

}  // namespace
}  // namespace mtc::core
