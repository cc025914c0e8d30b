// SPDX-License-Identifier: Apache-2.0
// RSM-14: bounded lock-free SPSC command queue. RSM-15: no heap.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "safestate/spsc_queue.hpp"

namespace {

using safestate::SpscQueue;

struct Payload {
  std::uint64_t seq{0};
  std::uint64_t check{0};  // = ~seq: detects torn reads of a slot
};

TEST(RSM14_SpscQueue, CapacityIsCompileTimeAndStorageIsInline) {
  static_assert(SpscQueue<int, 16>::capacity() == 16);
  static_assert(SpscQueue<int, 2>::capacity() == 2);
  static_assert(!std::is_copy_constructible_v<SpscQueue<int, 4>>);
  // The ring lives inside the object: no pointer to separately allocated storage.
  static_assert(sizeof(SpscQueue<Payload, 16>) >= 16 * sizeof(Payload));
  SpscQueue<int, 4> q;
  EXPECT_EQ(q.size(), 0u);
  EXPECT_TRUE(q.empty());
}

TEST(RSM14_SpscQueue, PopFromEmptyQueueFailsAndLeavesOutputUnchanged) {
  SpscQueue<int, 4> q;
  int out = 42;
  EXPECT_FALSE(q.try_pop(out));
  EXPECT_EQ(out, 42);
}

TEST(RSM14_SpscQueue, FullQueueRejectsAtOnceAndDropsNothing) {
  SpscQueue<int, 8> q;
  for (int i = 0; i < 8; ++i) {
    ASSERT_TRUE(q.try_push(i)) << i;
  }
  EXPECT_EQ(q.size(), 8u);
  // Further pushes are rejected, repeatedly, without blocking and without overwriting.
  for (int i = 100; i < 110; ++i) {
    EXPECT_FALSE(q.try_push(i));
  }
  EXPECT_EQ(q.size(), 8u);
  for (int i = 0; i < 8; ++i) {
    int out = -1;
    ASSERT_TRUE(q.try_pop(out));
    EXPECT_EQ(out, i);  // the queued elements survive intact, the rejected ones never appear
  }
  int out = -1;
  EXPECT_FALSE(q.try_pop(out));
  // Room again after popping.
  EXPECT_TRUE(q.try_push(7));
}

TEST(RSM14_SpscQueue, FifoOrder) {
  SpscQueue<int, 16> q;
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(q.try_push(i * 3));
  for (int i = 0; i < 10; ++i) {
    int out = 0;
    ASSERT_TRUE(q.try_pop(out));
    EXPECT_EQ(out, i * 3);
    EXPECT_EQ(q.size(), static_cast<std::size_t>(9 - i));
  }
}

TEST(RSM14_SpscQueue, WrapAroundKeepsOrderAndCapacity) {
  SpscQueue<int, 4> q;
  int next_in = 0;
  int next_out = 0;
  // Many laps with a varying fill level so every slot boundary is crossed repeatedly.
  for (int lap = 0; lap < 1000; ++lap) {
    const int pushes = 1 + lap % 4;
    for (int i = 0; i < pushes; ++i) {
      if (q.size() < q.capacity()) {
        ASSERT_TRUE(q.try_push(next_in++));
      } else {
        ASSERT_FALSE(q.try_push(-1));
      }
    }
    const int pops = 1 + (lap * 7) % 4;
    for (int i = 0; i < pops; ++i) {
      int out = -1;
      if (next_out < next_in) {
        ASSERT_TRUE(q.try_pop(out));
        ASSERT_EQ(out, next_out++);
      } else {
        ASSERT_FALSE(q.try_pop(out));
      }
    }
    ASSERT_EQ(q.size(), static_cast<std::size_t>(next_in - next_out));
  }
  EXPECT_GT(next_in, 1000);
}

TEST(RSM14_SpscQueue, TwoThreadStressNoLossNoDuplication) {
  constexpr std::uint64_t kCount = 500'000;
  SpscQueue<Payload, 16> q;
  std::atomic<bool> go{false};
  std::uint64_t rejected = 0;

  std::thread producer([&] {
    while (!go.load(std::memory_order_acquire)) {
    }
    for (std::uint64_t i = 0; i < kCount;) {
      if (q.try_push(Payload{i, ~i})) {
        ++i;
      } else {
        ++rejected;  // full: the producer learns it at once and retries; nothing is lost
        std::this_thread::yield();
      }
    }
  });

  std::vector<std::uint8_t> seen(kCount, 0);
  std::uint64_t expected = 0;
  bool order_ok = true;
  bool payload_ok = true;
  go.store(true, std::memory_order_release);
  while (expected < kCount) {
    Payload p;
    if (q.try_pop(p)) {
      if (p.check != ~p.seq) payload_ok = false;
      if (p.seq != expected) order_ok = false;
      if (p.seq < kCount) ++seen[p.seq];
      ++expected;
    } else {
      std::this_thread::yield();
    }
  }
  producer.join();

  EXPECT_TRUE(order_ok);
  EXPECT_TRUE(payload_ok);
  std::uint64_t missing = 0;
  std::uint64_t duplicated = 0;
  for (const std::uint8_t s : seen) {
    if (s == 0) ++missing;
    if (s > 1) ++duplicated;
  }
  EXPECT_EQ(missing, 0u);
  EXPECT_EQ(duplicated, 0u);
  Payload extra;
  EXPECT_FALSE(q.try_pop(extra));
  EXPECT_EQ(q.size(), 0u);
  // Informative: how often the producer found the queue full and retried.
  RecordProperty("producer_full_rejections", std::to_string(rejected));
}

}  // namespace
