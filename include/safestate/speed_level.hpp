// SPDX-License-Identifier: Apache-2.0
// Speed level (design §2, RSM-10).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// Abstract speed level of one cycle's joint velocities (§2): the model's speed input.
enum class SpeedLevel : std::uint8_t {
  Zero,
  Moving,
  OverT1,
};

inline constexpr std::size_t kSpeedLevelCount = 3;

inline constexpr std::array<SpeedLevel, kSpeedLevelCount> kAllSpeedLevels{
    SpeedLevel::Zero,
    SpeedLevel::Moving,
    SpeedLevel::OverT1,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(SpeedLevel v) noexcept {
  switch (v) {
    case SpeedLevel::Zero: return "ZERO";
    case SpeedLevel::Moving: return "MOVING";
    case SpeedLevel::OverT1: return "OVER_T1";
  }
  return "?";
}

}  // namespace safestate
