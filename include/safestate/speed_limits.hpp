// SPDX-License-Identifier: Apache-2.0
// The bounds a configured speed limit must respect (design §9 "Configuration bounds").
#pragma once

#include <cstdint>

namespace safestate {

/// ISO 10218-1:2011 §5.7.3 (reduced speed): in T1 the TCP speed shall not exceed 250 mm/s.
/// `Config::t1_speed_limit_mm_s` may be lower, never higher.
inline constexpr std::int32_t kIsoReducedSpeedMmS = 250;

/// Upper bound of `Config::t2_speed_limit_mm_s`: above what the default arm can reach at
/// all (UR5: 180 deg/s on every joint at 0.85 m reach is about 2.7 m/s at the tool), so a
/// T2 limit above it supervises nothing and is refused as a configuration error.
inline constexpr std::int32_t kMaxT2SpeedLimitMmS = 3000;

}  // namespace safestate
