// SPDX-License-Identifier: Apache-2.0
// Speed classification of one cycle's joint state (design §2, RSM-10).
#pragma once

#include <cstdint>

#include "safestate/arm_kinematics.hpp"
#include "safestate/config.hpp"
#include "safestate/joint_vector.hpp"
#include "safestate/speed_level.hpp"

namespace safestate {

/// ZERO when every |qd[i]| <= zero_velocity_rad_s; else OVER_T2 when the TCP speed
/// |J_v(q)·qd| exceeds the T2 limit, OVER_T1 when it exceeds the T1 limit, else MOVING.
/// A non-finite joint value (NaN/inf from a broken sensor) that is not already ZERO is
/// classified OVER_T2: an unreadable speed is treated as the most unsafe one.
class SpeedMonitor {
 public:
  explicit SpeedMonitor(const Config& config) noexcept;

  [[nodiscard]] SpeedLevel classify(const JointVector& q, const JointVector& qd) const noexcept;
  /// Linear TCP speed in mm/s.
  [[nodiscard]] double tcp_speed_mm_s(const JointVector& q, const JointVector& qd) const noexcept;

  [[nodiscard]] const ArmKinematics& kinematics() const noexcept { return kinematics_; }

 private:
  ArmKinematics kinematics_;
  double zero_velocity_rad_s_;
  double t1_speed_limit_mm_s_;
  double t2_speed_limit_mm_s_;
};

}  // namespace safestate
