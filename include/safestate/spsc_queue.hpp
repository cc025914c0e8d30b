// SPDX-License-Identifier: Apache-2.0
// Bounded lock-free single-producer / single-consumer ring buffer (RSM-14, RSM-15).
//
// * One producer thread calls try_push(), one consumer thread calls try_pop(); size() may be
//   called from either (it is a snapshot).
// * try_push() on a full queue returns false at once: the caller learns of the rejection,
//   nothing is dropped silently and the producer never blocks the consumer (no locks).
// * Storage is a std::array inside the object: no heap allocation, ever.
// * Indices are free-running std::size_t counters (head = next slot to read, tail = next
//   slot to write); the slot is index & (Capacity - 1). Wrap of the counters themselves is
//   harmless because Capacity is a power of two that divides 2^N.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <type_traits>

namespace safestate {

namespace detail {
/// Destructive-interference size; a constant so the layout does not depend on compiler flags.
inline constexpr std::size_t kCacheLine = 64;
}  // namespace detail

template <typename T, std::size_t Capacity>
class SpscQueue {
  static_assert(Capacity >= 2, "SpscQueue capacity must be at least 2");
  static_assert((Capacity & (Capacity - 1)) == 0, "SpscQueue capacity must be a power of two");
  static_assert(std::is_nothrow_copy_assignable_v<T>, "T must be nothrow copy-assignable");
  static_assert(std::is_nothrow_default_constructible_v<T>, "T must be nothrow default-constructible");
  static_assert(std::atomic<std::size_t>::is_always_lock_free, "size_t atomics must be lock-free");

 public:
  SpscQueue() noexcept = default;
  SpscQueue(const SpscQueue&) = delete;
  SpscQueue& operator=(const SpscQueue&) = delete;
  SpscQueue(SpscQueue&&) = delete;
  SpscQueue& operator=(SpscQueue&&) = delete;
  ~SpscQueue() = default;

  /// Producer side. Returns false (and changes nothing) when the queue is full.
  [[nodiscard]] bool try_push(const T& value) noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);  // only the producer writes it
    if (tail - cached_head_ >= Capacity) {
      cached_head_ = head_.load(std::memory_order_acquire);
      if (tail - cached_head_ >= Capacity) {
        return false;
      }
    }
    slots_[tail & kMask] = value;
    tail_.store(tail + 1, std::memory_order_release);  // publishes the slot to the consumer
    return true;
  }

  /// Consumer side. Returns false (and leaves `out` unchanged) when the queue is empty.
  [[nodiscard]] bool try_pop(T& out) noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);  // only the consumer writes it
    if (head == cached_tail_) {
      cached_tail_ = tail_.load(std::memory_order_acquire);
      if (head == cached_tail_) {
        return false;
      }
    }
    out = slots_[head & kMask];
    head_.store(head + 1, std::memory_order_release);  // hands the slot back to the producer
    return true;
  }

  /// Number of queued elements (exact when called from a quiescent queue; otherwise a
  /// snapshot that lies between the values before and after concurrent operations).
  [[nodiscard]] std::size_t size() const noexcept {
    const std::size_t head = head_.load(std::memory_order_acquire);
    const std::size_t tail = tail_.load(std::memory_order_acquire);
    const std::size_t n = tail - head;
    return n > Capacity ? Capacity : n;  // a torn snapshot can never report more than Capacity
  }

  [[nodiscard]] bool empty() const noexcept { return size() == 0; }

  [[nodiscard]] static constexpr std::size_t capacity() noexcept { return Capacity; }

 private:
  static constexpr std::size_t kMask = Capacity - 1;

  // Consumer-owned line: read index and the consumer's cached copy of the write index.
  alignas(detail::kCacheLine) std::atomic<std::size_t> head_{0};
  std::size_t cached_tail_{0};
  // Producer-owned line: write index and the producer's cached copy of the read index.
  alignas(detail::kCacheLine) std::atomic<std::size_t> tail_{0};
  std::size_t cached_head_{0};
  // Payload on its own line(s).
  alignas(detail::kCacheLine) std::array<T, Capacity> slots_{};
};

}  // namespace safestate
