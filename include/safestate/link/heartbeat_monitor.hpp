// SPDX-License-Identifier: Apache-2.0
// The operator link's heartbeat, as the control cycle sees it (design §11, row C26).
//
// The bridge thread (non-real-time) calls beat() for every heartbeat of the controlling
// client; the control thread calls sample() once per cycle and puts the result into
// ScanInputs::operator_link_ok. The only shared datum is one atomic counter: the cycle
// never waits on the bridge, and a hung bridge looks like a silent client (the counter
// stops), which is the safe reading.
#pragma once

#include <atomic>
#include <cstdint>

#include "safestate/spsc_queue.hpp"  // detail::kCacheLine

namespace safestate::link {

/// 100 ms at the default 1 ms cycle: the documented heartbeat period (design §11).
inline constexpr std::uint32_t kHeartbeatPeriodCycles = 100;

class HeartbeatMonitor {
 public:
  explicit constexpr HeartbeatMonitor(std::uint32_t period_cycles = kHeartbeatPeriodCycles) noexcept
      : period_(period_cycles), age_(period_cycles + 1) {}

  HeartbeatMonitor(const HeartbeatMonitor&) = delete;
  HeartbeatMonitor& operator=(const HeartbeatMonitor&) = delete;
  HeartbeatMonitor(HeartbeatMonitor&&) = delete;
  HeartbeatMonitor& operator=(HeartbeatMonitor&&) = delete;
  ~HeartbeatMonitor() = default;

  /// Bridge side, any one thread: the controlling client's heartbeat arrived.
  void beat() noexcept { count_.fetch_add(1, std::memory_order_release); }

  /// Control thread, once per cycle: TRUE while the last heartbeat is at most the period
  /// old. Before the first heartbeat the link reads lost. Wait-free, no allocation.
  [[nodiscard]] bool sample() noexcept {
    const std::uint32_t c = count_.load(std::memory_order_acquire);
    if (c != seen_) {
      seen_ = c;
      age_ = 0;
    } else if (age_ <= period_) {
      ++age_;  // saturates at period + 1: lost
    }
    return age_ <= period_;
  }

  /// Cycles since the last heartbeat the control thread saw (period + 1 = lost).
  [[nodiscard]] std::uint32_t age_cycles() const noexcept { return age_; }
  [[nodiscard]] std::uint32_t period_cycles() const noexcept { return period_; }

 private:
  // The bridge writes count_; the control thread alone writes the rest (own cache lines).
  alignas(detail::kCacheLine) std::atomic<std::uint32_t> count_{0};
  alignas(detail::kCacheLine) std::uint32_t seen_{0};  // control thread only
  std::uint32_t period_;
  std::uint32_t age_;  // control thread only
};

}  // namespace safestate::link
