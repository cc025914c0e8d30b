// SPDX-License-Identifier: Apache-2.0
// A single-writer seqlock: the control cycle publishes a snapshot every cycle, wait-free;
// any number of readers (the bridge) copy the latest consistent one (design §11).
//
// * write() never waits, never allocates: two counter stores around a word-wise copy.
// * try_read() returns false when the copy was torn by a concurrent write (the reader
//   retries; read() retries a bounded number of times). Readers never block the writer.
// * The payload is held as relaxed atomic 64-bit words, so concurrent access is not a
//   data race in the C++ memory model (a torn copy is detected by the sequence number).
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace safestate::link {

/// Cache-line aligned and sized: its lines are shared with no other data.
template <typename T>
class alignas(64) Seqlock {
  static_assert(std::is_trivially_copyable_v<T>, "Seqlock<T>: T must be trivially copyable");
  static_assert(std::atomic<std::uint64_t>::is_always_lock_free, "64-bit atomics must be lock-free");
  static constexpr std::size_t kWords = (sizeof(T) + sizeof(std::uint64_t) - 1) / sizeof(std::uint64_t);

 public:
  Seqlock() noexcept = default;
  Seqlock(const Seqlock&) = delete;
  Seqlock& operator=(const Seqlock&) = delete;
  Seqlock(Seqlock&&) = delete;
  Seqlock& operator=(Seqlock&&) = delete;
  ~Seqlock() = default;

  /// Writer (one thread only).
  void write(const T& value) noexcept {
    std::array<std::uint64_t, kWords> words{};
    std::memcpy(words.data(), static_cast<const void*>(&value), sizeof(T));
    const std::uint64_t s = seq_.load(std::memory_order_relaxed);
    seq_.store(s + 1, std::memory_order_relaxed);  // odd: write in progress
    std::atomic_thread_fence(std::memory_order_release);
    for (std::size_t i = 0; i < kWords; ++i) words_[i].store(words[i], std::memory_order_relaxed);
    seq_.store(s + 2, std::memory_order_release);  // even: published
  }

  /// Reader: a consistent copy into `out` and TRUE, or FALSE when none was published yet
  /// or a write overlapped the copy.
  [[nodiscard]] bool try_read(T& out) const noexcept {
    const std::uint64_t before = seq_.load(std::memory_order_acquire);
    if (before == 0 || (before & 1U) != 0) return false;
    std::array<std::uint64_t, kWords> words{};
    for (std::size_t i = 0; i < kWords; ++i) words[i] = words_[i].load(std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_acquire);
    if (seq_.load(std::memory_order_relaxed) != before) return false;
    std::memcpy(static_cast<void*>(&out), words.data(), sizeof(T));
    return true;
  }

  /// Reader: try_read() up to `attempts` times.
  [[nodiscard]] bool read(T& out, int attempts = 64) const noexcept {
    for (int i = 0; i < attempts; ++i) {
      if (try_read(out)) return true;
    }
    return false;
  }

  /// Number of completed writes.
  [[nodiscard]] std::uint64_t version() const noexcept { return seq_.load(std::memory_order_acquire) / 2; }

 private:
  std::atomic<std::uint64_t> seq_{0};
  std::array<std::atomic<std::uint64_t>, kWords> words_{};
};

}  // namespace safestate::link
