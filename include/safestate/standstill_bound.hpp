// SPDX-License-Identifier: Apache-2.0
// How fast the tool centre point can move while every joint reads "at rest" (design §9
// "Configuration bounds"): the zero-velocity threshold seen at the tool.
#pragma once

#include <array>
#include <cmath>

#include "safestate/dh_table.hpp"

namespace safestate {

/// An upper bound (mm/s) of the TCP speed when every |qd[i]| <= zero_velocity_rad_s.
/// Joint i turns about an axis through the origin of frame i-1; the TCP lies at most
/// L_i = sum_{j >= i} sqrt(a_j^2 + d_j^2) + |tool| from that origin (triangle inequality
/// along the DH chain), so |v_tcp| <= sum_i |qd_i| L_i <= zero_velocity_rad_s * sum_i L_i.
/// Independent of the pose, so it can be checked once on the Config.
[[nodiscard]] inline double zero_class_tcp_bound_mm_s(const DhTable& dh, const std::array<double, 3>& tool_offset_m,
                                                      double zero_velocity_rad_s) noexcept {
  const double tool = std::sqrt(tool_offset_m[0] * tool_offset_m[0] + tool_offset_m[1] * tool_offset_m[1] +
                                tool_offset_m[2] * tool_offset_m[2]);
  double lever = tool;  // L_i, accumulated from the last joint back to the first
  double sum = 0.0;
  for (std::size_t k = dh.size(); k-- > 0;) {
    lever += std::sqrt(dh[k].a_m * dh[k].a_m + dh[k].d_m * dh[k].d_m);
    sum += lever;
  }
  return 1000.0 * zero_velocity_rad_s * sum;
}

}  // namespace safestate
