// SPDX-License-Identifier: Apache-2.0
// Dual-channel safety input with discrepancy monitoring (design §3, RSM-04).
#pragma once

#include <cstdint>

#include "safestate/channel_pair.hpp"
#include "safestate/enable_position.hpp"

namespace safestate {

/// The healthy (not tripped) level of one channel, per channel type.
template <typename T>
struct ChannelTraits;

/// E-stop and safeguard: a closed contact (true) is healthy; false is a demand.
template <>
struct ChannelTraits<bool> {
  [[nodiscard]] static constexpr bool healthy(bool v) noexcept { return v; }
};

/// Enabling device: only MIDDLE permits motion; RELEASED and PANIC are demands.
template <>
struct ChannelTraits<EnablePosition> {
  [[nodiscard]] static constexpr bool healthy(EnablePosition v) noexcept { return v == EnablePosition::Middle; }
};

/// Monitors one dual-channel input. Every cycle, in every state:
///     mismatch := (a != b) ? min(mismatch + 1, D + 1) : 0
/// Exactly D mismatching cycles are tolerated; the (D+1)-th is a discrepancy fault.
/// Tripping is 1oo2 and immediate: either channel at a non-healthy level trips the function.
template <typename T>
class DualChannelInput {
 public:
  constexpr explicit DualChannelInput(std::uint32_t discrepancy_cycles) noexcept
      : discrepancy_cycles_(discrepancy_cycles) {}

  /// One scan cycle's reading.
  constexpr void update(const ChannelPair<T>& reading) noexcept {
    channels_ = reading;
    if (reading.a != reading.b) {
      // Saturates at D + 1: written as a comparison so D near the type's maximum cannot wrap.
      if (mismatch_ <= discrepancy_cycles_) {
        ++mismatch_;
      }
    } else {
      mismatch_ = 0;
    }
  }

  /// Either channel demands (1oo2).
  [[nodiscard]] constexpr bool tripped() const noexcept {
    return !ChannelTraits<T>::healthy(channels_.a) || !ChannelTraits<T>::healthy(channels_.b);
  }
  /// Both channels at `v` (e.g. enable_middle).
  [[nodiscard]] constexpr bool both(T v) const noexcept { return channels_.a == v && channels_.b == v; }
  /// At least one channel at `v` (e.g. enable_panic).
  [[nodiscard]] constexpr bool either(T v) const noexcept { return channels_.a == v || channels_.b == v; }

  /// Consecutive cycles the channels have disagreed, saturated at D + 1.
  [[nodiscard]] constexpr std::uint32_t mismatch_cycles() const noexcept { return mismatch_; }
  /// The channels disagreed for longer than the discrepancy time.
  [[nodiscard]] constexpr bool discrepancy_fault() const noexcept { return mismatch_ > discrepancy_cycles_; }
  [[nodiscard]] constexpr const ChannelPair<T>& channels() const noexcept { return channels_; }
  [[nodiscard]] constexpr std::uint32_t discrepancy_cycles() const noexcept { return discrepancy_cycles_; }

 private:
  std::uint32_t discrepancy_cycles_;
  std::uint32_t mismatch_{0};
  ChannelPair<T> channels_{};  // tripped until the first reading
};

}  // namespace safestate
