// SPDX-License-Identifier: Apache-2.0
// The real-time side of the operator link (design §11): the control thread that runs the
// SystemStateManager against the simulated cell every cycle. Per cycle it reads two atomic
// words (plant switches, heartbeat counter), runs one cycle, pushes the popped command's
// result into a wait-free SPSC queue and publishes a CellStatus through the seqlock.
// Nothing in run_one_cycle() allocates, locks or waits on the bridge.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>

#include "safestate/config.hpp"
#include "safestate/link/cell_status.hpp"
#include "safestate/link/heartbeat_monitor.hpp"
#include "safestate/link/plant_switches.hpp"
#include "safestate/link/seqlock.hpp"
#include "safestate/sim/cell_plant.hpp"
#include "safestate/spsc_queue.hpp"
#include "safestate/system_state_manager.hpp"

namespace safestate::link {

/// Cycle execution times, 0.1 us buckets up to 1 ms (the last one is "more").
class CycleTimeHistogram {
 public:
  static constexpr std::size_t kBuckets = 10001;
  void add(std::uint64_t ns) noexcept {
    const std::uint64_t tenth_us = ns / 100;
    ++buckets_[tenth_us < kBuckets - 1 ? tenth_us : kBuckets - 1];
    ++count_;
    if (ns > max_ns_) max_ns_ = ns;
  }
  /// Adds another histogram's samples (the bench sums its rounds).
  void merge(const CycleTimeHistogram& other) noexcept {
    for (std::size_t i = 0; i < kBuckets; ++i) buckets_[i] += other.buckets_[i];
    count_ += other.count_;
    if (other.max_ns_ > max_ns_) max_ns_ = other.max_ns_;
  }
  void clear() noexcept {
    buckets_.fill(0);
    count_ = 0;
    max_ns_ = 0;
  }
  /// The bucket bound (us, 0.1 us steps) below which `fraction` of the samples lie.
  [[nodiscard]] double percentile_us(double fraction) const noexcept;
  [[nodiscard]] std::uint64_t count() const noexcept { return count_; }
  [[nodiscard]] double max_us() const noexcept { return static_cast<double>(max_ns_) / 1000.0; }

 private:
  std::array<std::uint64_t, kBuckets> buckets_{};
  std::uint64_t count_{0};
  std::uint64_t max_ns_{0};
};

class ControlLoop {
 public:
  using OutcomeQueue = SpscQueue<CommandOutcome, 64>;

  explicit ControlLoop(const Config& config = sim::demo_cell_config()) noexcept;

  // ---- bridge side (one producer thread) ----
  [[nodiscard]] SubmitResult submit(const Command& c) noexcept { return manager_.submit(c); }
  void set_plant(const PlantSwitches& s) noexcept { plant_word_.store(s.pack(), std::memory_order_release); }
  [[nodiscard]] PlantSwitches plant() const noexcept {
    return PlantSwitches::unpack(plant_word_.load(std::memory_order_acquire));
  }
  HeartbeatMonitor& heartbeat() noexcept { return heartbeat_; }
  [[nodiscard]] bool pop_outcome(CommandOutcome& out) noexcept { return outcomes_.try_pop(out); }
  [[nodiscard]] bool read_status(CellStatus& out) const noexcept { return status_.read(out); }
  [[nodiscard]] std::uint64_t outcomes_dropped() const noexcept {
    return outcomes_dropped_.load(std::memory_order_relaxed);
  }

  // ---- control thread ----
  /// One cycle: inputs from the plant and the heartbeat, the manager, the plant's reaction,
  /// the result of a popped command, the status snapshot. Wait-free, no heap.
  void run_one_cycle() noexcept;
  /// Runs cycles every `period` until `stop` is set; measures each cycle's execution time.
  void run(const std::atomic<bool>& stop, std::chrono::microseconds period) noexcept;
  [[nodiscard]] const CycleTimeHistogram& cycle_times() const noexcept { return times_; }
  /// Control thread only, or when it is stopped.
  void clear_cycle_times() noexcept { clear_times_.store(true, std::memory_order_release); }
  [[nodiscard]] std::uint64_t cycles() const noexcept { return cycles_.load(std::memory_order_acquire); }
  [[nodiscard]] const SystemStateManager& manager() const noexcept { return manager_; }

 private:
  // What the control thread alone touches first; every word the bridge writes or reads sits
  // on cache lines of its own, so the bridge's activity costs the cycle no false sharing.
  SystemStateManager manager_;
  sim::CellPlant plant_;
  CellStatus snapshot_{};
  CycleTimeHistogram times_;
  HeartbeatMonitor heartbeat_;
  alignas(detail::kCacheLine) std::atomic<std::uint32_t> plant_word_{PlantSwitches{}.pack()};
  alignas(detail::kCacheLine) std::atomic<bool> clear_times_{false};
  OutcomeQueue outcomes_;
  alignas(detail::kCacheLine) std::atomic<std::uint64_t> outcomes_dropped_{0};
  std::atomic<std::uint64_t> cycles_{0};
  Seqlock<CellStatus> status_;
};

}  // namespace safestate::link
