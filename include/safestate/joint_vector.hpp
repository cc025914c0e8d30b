// SPDX-License-Identifier: Apache-2.0
// Joint-space vector of the 6-axis arm (positions in rad, velocities in rad/s).
#pragma once

#include <array>
#include <cstddef>

namespace safestate {

/// Number of robot axes (RSM-17: one PLCopen axis state machine per axis).
inline constexpr std::size_t kAxisCount = 6;

/// One value per joint, fixed size, no heap (RSM-15).
using JointVector = std::array<double, kAxisCount>;

}  // namespace safestate
