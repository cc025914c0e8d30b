// SPDX-License-Identifier: Apache-2.0
#include "safestate/speed_monitor.hpp"

#include <cmath>

namespace safestate {

SpeedMonitor::SpeedMonitor(const Config& config) noexcept
    : kinematics_(config.dh, tool_offset_or_flange(config)),
      zero_velocity_rad_s_(config.zero_velocity_rad_s),
      t1_speed_limit_mm_s_(static_cast<double>(config.t1_speed_limit_mm_s)),
      t2_speed_limit_mm_s_(static_cast<double>(config.t2_speed_limit_mm_s)) {}

double SpeedMonitor::tcp_speed_mm_s(const JointVector& q, const JointVector& qd) const noexcept {
  return kinematics_.tcp_speed_mm_s(q, qd);
}

SpeedLevel SpeedMonitor::classify(const JointVector& q, const JointVector& qd) const noexcept {
  bool at_rest = true;
  for (const double v : qd) {
    // Written so that NaN is "not at rest".
    if (!(std::fabs(v) <= zero_velocity_rad_s_)) {
      at_rest = false;
    }
  }
  if (at_rest) {
    return SpeedLevel::Zero;
  }
  const double tcp = tcp_speed_mm_s(q, qd);
  // NaN/inf (unreadable sensor) counts as over every limit: the unsafe reading.
  if (!std::isfinite(tcp) || tcp > t2_speed_limit_mm_s_) {
    return SpeedLevel::OverT2;
  }
  if (tcp > t1_speed_limit_mm_s_) {
    return SpeedLevel::OverT1;
  }
  return SpeedLevel::Moving;
}

}  // namespace safestate
