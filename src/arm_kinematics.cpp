// SPDX-License-Identifier: Apache-2.0
#include "safestate/arm_kinematics.hpp"

#include <cmath>
#include <cstddef>

namespace safestate {

ArmKinematics::ArmKinematics(const DhTable& dh, const std::array<double, 3>& tool_offset_m) noexcept
    : dh_(dh), tool_offset_m_(tool_offset_m[0], tool_offset_m[1], tool_offset_m[2]) {}

Eigen::Isometry3d ArmKinematics::link_transform(const DhRow& row, double theta) noexcept {
  const double th = theta + row.theta_offset_rad;
  const double ct = std::cos(th);
  const double st = std::sin(th);
  const double ca = std::cos(row.alpha_rad);
  const double sa = std::sin(row.alpha_rad);
  // Rot_z(th) * Trans_z(d) * Trans_x(a) * Rot_x(alpha)
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.matrix() << ct, -st * ca, st * sa, row.a_m * ct,  //
      st, ct * ca, -ct * sa, row.a_m * st,            //
      0.0, sa, ca, row.d_m,                           //
      0.0, 0.0, 0.0, 1.0;
  return t;
}

Eigen::Isometry3d ArmKinematics::forward(const JointVector& q) const noexcept {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < kAxisCount; ++i) {
    t = t * link_transform(dh_[i], q[i]);
  }
  t.translate(tool_offset_m_);  // flange -> tool centre point
  return t;
}

ArmKinematics::Jacobian ArmKinematics::jacobian(const JointVector& q) const noexcept {
  // Axes z_i and origins p_i of frames 0..5 (frame i is the one joint i+1 rotates about).
  std::array<Eigen::Vector3d, kAxisCount> z{};
  std::array<Eigen::Vector3d, kAxisCount> p{};
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < kAxisCount; ++i) {
    z[i] = t.linear().col(2);
    p[i] = t.translation();
    t = t * link_transform(dh_[i], q[i]);
  }
  const Eigen::Vector3d pe = t * tool_offset_m_;  // the tool centre point

  Jacobian j;
  for (std::size_t i = 0; i < kAxisCount; ++i) {
    const auto col = static_cast<Eigen::Index>(i);
    j.block<3, 1>(0, col) = z[i].cross(pe - p[i]);
    j.block<3, 1>(3, col) = z[i];
  }
  return j;
}

double ArmKinematics::tcp_speed_mm_s(const JointVector& q, const JointVector& qd) const noexcept {
  const Jacobian j = jacobian(q);
  const Eigen::Matrix<double, 6, 1> qdv = Eigen::Map<const Eigen::Matrix<double, 6, 1>>(qd.data());
  const Eigen::Vector3d v = j.topRows<3>() * qdv;
  return v.norm() * 1000.0;
}

}  // namespace safestate
