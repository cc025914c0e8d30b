// SPDX-License-Identifier: Apache-2.0
// Forward kinematics, geometric Jacobian and TCP speed of the 6-axis arm (RSM-10).
//
// Fixed-size Eigen types only: no heap allocation, bounded work (RSM-15). Every call costs
// six DH transforms plus one 3x6 product; nothing depends on the input values.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>

#include "safestate/dh_table.hpp"
#include "safestate/joint_vector.hpp"

namespace safestate {

class ArmKinematics {
 public:
  using Jacobian = Eigen::Matrix<double, 6, 6>;

  /// Copies the table; the object is self-contained and trivially copyable.
  explicit ArmKinematics(const DhTable& dh, const std::array<double, 3>& tool_offset_m = {0.0, 0.0, 0.0}) noexcept;

  /// Pose of the tool centre point (the last DH frame moved by the tool offset) in the base
  /// frame, metres.
  [[nodiscard]] Eigen::Isometry3d forward(const JointVector& q) const noexcept;

  /// Geometric Jacobian in the base frame: rows 0..2 linear velocity (m/s per rad/s),
  /// rows 3..5 angular velocity. Column i (joint i+1, revolute):
  ///   J_v,i = z_i x (p_e - p_i),  J_w,i = z_i
  /// with z_i, p_i the axis and origin of DH frame i (frame 0 = base), p_e the TCP.
  [[nodiscard]] Jacobian jacobian(const JointVector& q) const noexcept;

  /// Linear TCP speed |J_v(q) · qd| in mm/s (q in rad, qd in rad/s).
  [[nodiscard]] double tcp_speed_mm_s(const JointVector& q, const JointVector& qd) const noexcept;

  [[nodiscard]] const DhTable& dh() const noexcept { return dh_; }

  /// Classic DH link transform ^{i-1}T_i for joint angle `theta` (offset added here).
  [[nodiscard]] static Eigen::Isometry3d link_transform(const DhRow& row, double theta) noexcept;

 private:
  DhTable dh_;
  Eigen::Vector3d tool_offset_m_;
};

}  // namespace safestate
