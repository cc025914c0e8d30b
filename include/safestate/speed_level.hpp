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
  OverT2,  ///< TCP speed above the T2 limit (so above T1's too), or unreadable
};

inline constexpr std::size_t kSpeedLevelCount = 4;

inline constexpr std::array<SpeedLevel, kSpeedLevelCount> kAllSpeedLevels{
    SpeedLevel::Zero,
    SpeedLevel::Moving,
    SpeedLevel::OverT1,
    SpeedLevel::OverT2,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(SpeedLevel v) noexcept {
  switch (v) {
    case SpeedLevel::Zero: return "ZERO";
    case SpeedLevel::Moving: return "MOVING";
    case SpeedLevel::OverT1: return "OVER_T1";
    case SpeedLevel::OverT2: return "OVER_T2";
  }
  return "?";
}

}  // namespace safestate
