// SPDX-License-Identifier: Apache-2.0
// The fieldbus and cycle watchdog (design §2 "Fieldbus watchdog", C24): computed in the core
// from the process image's cycle counter and working counter, every cycle.
#pragma once

#include <cstdint>

namespace safestate {

/// Upper bound of `Config::fieldbus_lost_cycles_limit`: the drives' own EtherCAT SyncManager
/// watchdog (100 ms by default) must not act before the manager has noticed the loss.
inline constexpr std::uint32_t kMaxFieldbusLostCycles = 100;

/// Each cycle reads the process image of the last bus frame: its cycle counter (incremented
/// by the master once per bus cycle, wrapping at 2^16) and its working counter (WKC: each
/// slave that processed the datagram adds to it). The cycle has a fresh, complete frame when
/// the WKC equals the expected one and the counter advanced by exactly one. Otherwise
///   - WKC wrong: a slave did not process the frame (its data are stale or missing);
///   - counter unchanged: no new frame arrived since the last cycle (bus stalled);
///   - counter advanced by k > 1: the control cycle missed k - 1 frames (cycle overrun);
/// each counts as missed cycles in a row. More than `lost_cycles_limit` in a row is a loss,
/// latched: only re-initialisation clears it (C24 locks out anyway).
/// The first complete frame sets the counter reference. A zero-initialised image (WKC 0)
/// reads as a loss, as every zero input does.
class FieldbusWatchdog {
 public:
  constexpr FieldbusWatchdog(std::uint16_t expected_working_counter, std::uint32_t lost_cycles_limit) noexcept
      : expected_wkc_(expected_working_counter), limit_(lost_cycles_limit) {}

  /// One cycle's reading; returns healthy() after it.
  constexpr bool update(std::uint16_t cycle_counter, std::uint16_t working_counter) noexcept {
    if (working_counter != expected_wkc_ || expected_wkc_ == 0U) {
      missed_ = saturate(static_cast<std::uint64_t>(missed_) + 1U);
    } else if (!has_reference_) {
      has_reference_ = true;
      last_counter_ = cycle_counter;
      missed_ = 0;
    } else {
      const auto advanced = static_cast<std::uint16_t>(cycle_counter - last_counter_);
      last_counter_ = cycle_counter;
      missed_ = advanced == 0U ? saturate(static_cast<std::uint64_t>(missed_) + 1U) : saturate(advanced - 1U);
    }
    lost_ = lost_ || missed_ > limit_;
    return healthy();
  }

  [[nodiscard]] constexpr bool healthy() const noexcept { return !lost_; }
  /// Missed cycles in a row (saturated at the limit + 1).
  [[nodiscard]] constexpr std::uint32_t missed_cycles() const noexcept { return missed_; }
  [[nodiscard]] constexpr bool has_reference() const noexcept { return has_reference_; }
  /// The counter of the last complete frame (meaningful once has_reference()).
  [[nodiscard]] constexpr std::uint16_t last_counter() const noexcept { return last_counter_; }
  [[nodiscard]] constexpr std::uint16_t expected_working_counter() const noexcept { return expected_wkc_; }

 private:
  [[nodiscard]] constexpr std::uint32_t saturate(std::uint64_t n) const noexcept {
    const std::uint64_t cap = static_cast<std::uint64_t>(limit_) + 1U;
    return static_cast<std::uint32_t>(n < cap ? n : cap);
  }

  std::uint16_t expected_wkc_;
  std::uint32_t limit_;
  std::uint32_t missed_{0};
  std::uint16_t last_counter_{0};
  bool has_reference_{false};
  bool lost_{false};
};

}  // namespace safestate
