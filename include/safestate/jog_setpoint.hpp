// SPDX-License-Identifier: Apache-2.0
// The jog carried by MANUAL_JOGGING and by a paused jog (design §4 `jog`).
#pragma once

#include <cstdint>

namespace safestate {

/// (axis 1..6, direction ±1, speed mm/s); (0, 0, 0) where no jog is meaningful.
struct JogSetpoint {
  std::int32_t axis{0};
  std::int32_t direction{0};
  std::int32_t speed_mm_s{0};

  [[nodiscard]] constexpr bool operator==(const JogSetpoint& o) const noexcept {
    return axis == o.axis && direction == o.direction && speed_mm_s == o.speed_mm_s;
  }
  [[nodiscard]] constexpr bool operator!=(const JogSetpoint& o) const noexcept { return !(*this == o); }
};

}  // namespace safestate
