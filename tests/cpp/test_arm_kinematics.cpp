// SPDX-License-Identifier: Apache-2.0
// RSM-10: TCP speed from forward kinematics and the Jacobian of the UR5 (classic DH).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

#include "safestate/arm_kinematics.hpp"
#include "safestate/dh_table.hpp"

namespace {

using safestate::ArmKinematics;
using safestate::JointVector;
using safestate::kAxisCount;
using safestate::kUr5DhTable;

constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfPi = kPi / 2.0;

// UR5 DH lengths (metres), written out again so the expectations below are hand arithmetic.
constexpr double d1 = 0.089159;
constexpr double a2 = -0.425;
constexpr double a3 = -0.39225;
constexpr double d4 = 0.10915;
constexpr double d5 = 0.09465;
constexpr double d6 = 0.0823;

void expect_vec_near(const Eigen::Vector3d& got, const Eigen::Vector3d& want, double tol) {
  EXPECT_NEAR(got.x(), want.x(), tol) << "got " << got.transpose() << " want " << want.transpose();
  EXPECT_NEAR(got.y(), want.y(), tol) << "got " << got.transpose() << " want " << want.transpose();
  EXPECT_NEAR(got.z(), want.z(), tol) << "got " << got.transpose() << " want " << want.transpose();
}

TEST(RSM10_DhTable, Ur5PublishedParameters) {
  EXPECT_DOUBLE_EQ(kUr5DhTable[0].d_m, d1);
  EXPECT_DOUBLE_EQ(kUr5DhTable[1].a_m, a2);
  EXPECT_DOUBLE_EQ(kUr5DhTable[2].a_m, a3);
  EXPECT_DOUBLE_EQ(kUr5DhTable[3].d_m, d4);
  EXPECT_DOUBLE_EQ(kUr5DhTable[4].d_m, d5);
  EXPECT_DOUBLE_EQ(kUr5DhTable[5].d_m, d6);
  EXPECT_DOUBLE_EQ(kUr5DhTable[0].alpha_rad, kHalfPi);
  EXPECT_DOUBLE_EQ(kUr5DhTable[1].alpha_rad, 0.0);
  EXPECT_DOUBLE_EQ(kUr5DhTable[2].alpha_rad, 0.0);
  EXPECT_DOUBLE_EQ(kUr5DhTable[3].alpha_rad, kHalfPi);
  EXPECT_DOUBLE_EQ(kUr5DhTable[4].alpha_rad, -kHalfPi);
  EXPECT_DOUBLE_EQ(kUr5DhTable[5].alpha_rad, 0.0);
}

// Zero pose, by hand. Each classic DH link is Rot_z(theta) Trans_z(d) Trans_x(a) Rot_x(alpha).
//   Link 1: origin (0, 0, d1); Rot_x(+90°): x1 = x0, y1 = z0, z1 = -y0.
//   Link 2: + a2 along x1           -> p2 = (a2, 0, d1)
//   Link 3: + a3 along x2 (= x0)    -> p3 = (a2 + a3, 0, d1)
//   Link 4: + d4 along z3 (= -y0)   -> p4 = (a2 + a3, -d4, d1);  Rot_x(+90°): z4 = -z0
//   Link 5: + d5 along z4 (= -z0)   -> p5 = (a2 + a3, -d4, d1 - d5); Rot_x(-90°): z5 = -y0
//   Link 6: + d6 along z5 (= -y0)   -> p6 = (a2 + a3, -d4 - d6, d1 - d5)
//   = (-0.425 - 0.39225, -(0.10915 + 0.0823), 0.089159 - 0.09465)
//   = (-0.81725, -0.19145, -0.005491) m.
//   Flange orientation: x6 = x0, y6 = z0, z6 = -y0.
TEST(RSM10_ArmKinematics, Ur5ZeroPoseFlangeMatchesHandComputation) {
  const ArmKinematics kin{kUr5DhTable};
  const Eigen::Isometry3d t = kin.forward(JointVector{});
  expect_vec_near(t.translation(), Eigen::Vector3d(-0.81725, -0.19145, -0.005491), 1e-12);
  expect_vec_near(t.linear().col(0), Eigen::Vector3d(1, 0, 0), 1e-12);
  expect_vec_near(t.linear().col(1), Eigen::Vector3d(0, 0, 1), 1e-12);
  expect_vec_near(t.linear().col(2), Eigen::Vector3d(0, -1, 0), 1e-12);
}

// q = (90°, -90°, 90°, 0, 0, 0), by hand (first without joint 1, then rotate about z0):
//   Link 1: p1 = (0, 0, d1); x1 = x0, y1 = z0, z1 = -y0.
//   Link 2 (theta -90°): + a2 along x2, x2 = R1·(cos -90°, sin -90°, 0) = -y1 = -z0
//     -> p2 = (0, 0, d1 - a2) = (0, 0, 0.514159); y2 = x1 = x0, z2 = -y0.
//   Link 3 (theta +90°): x3 = y2 = x0, y3 = -x2 = z0, z3 = -y0; + a3 along x3
//     -> p3 = (a3, 0, d1 - a2) = (-0.39225, 0, 0.514159)
//   Link 4: + d4 along z3 (= -y0) -> p4 = (a3, -d4, 0.514159); Rot_x(+90°): y4 = -y0, z4 = -z0
//   Link 5: + d5 along z4 (= -z0) -> p5 = (a3, -d4, 0.514159 - d5 = 0.419509);
//           Rot_x(-90°): x5 = x0, y5 = z0, z5 = -y0
//   Link 6: + d6 along z5 (= -y0) -> p6 = (a3, -d4 - d6, 0.419509) = (-0.39225, -0.19145, 0.419509)
//   Joint 1 at +90° rotates everything about z0: (x, y, z) -> (-y, x, z)
//   => p6 = (0.19145, -0.39225, 0.419509); x6 = y0, y6 = z0, z6 = x0.
TEST(RSM10_ArmKinematics, Ur5RightAnglePoseMatchesHandComputation) {
  const ArmKinematics kin{kUr5DhTable};
  const JointVector q{kHalfPi, -kHalfPi, kHalfPi, 0.0, 0.0, 0.0};
  const Eigen::Isometry3d t = kin.forward(q);
  expect_vec_near(t.translation(), Eigen::Vector3d(0.19145, -0.39225, 0.419509), 1e-12);
  expect_vec_near(t.linear().col(0), Eigen::Vector3d(0, 1, 0), 1e-12);
  expect_vec_near(t.linear().col(1), Eigen::Vector3d(0, 0, 1), 1e-12);
  expect_vec_near(t.linear().col(2), Eigen::Vector3d(1, 0, 0), 1e-12);
}

// Shoulder straight up, q = (0, -90°, 0, 0, 0, 0): p2 = (0, 0, d1 - a2), the forearm continues
// up (x3 = -z0): p3 = (0, 0, d1 - a2 - a3) = (0, 0, 0.906409); then the wrist offsets
// -d4 - d6 along y0 and -d5 along x0 (z4 = -x0):  p6 = (-0.09465, -0.19145, 0.906409).
TEST(RSM10_ArmKinematics, Ur5UprightPoseMatchesHandComputation) {
  const ArmKinematics kin{kUr5DhTable};
  const JointVector q{0.0, -kHalfPi, 0.0, 0.0, 0.0, 0.0};
  expect_vec_near(kin.forward(q).translation(), Eigen::Vector3d(-d5, -d4 - d6, d1 - a2 - a3), 1e-12);
  expect_vec_near(kin.forward(q).translation(), Eigen::Vector3d(-0.09465, -0.19145, 0.906409), 1e-12);
}

// Central finite difference of forward(): linear rows d p / d q_i, angular rows from
// R(q + h e_i) R(q - h e_i)^T ~ rotation by 2h·omega_i.
ArmKinematics::Jacobian numeric_jacobian(const ArmKinematics& kin, const JointVector& q, double h) {
  ArmKinematics::Jacobian j;
  for (std::size_t i = 0; i < kAxisCount; ++i) {
    JointVector qp = q;
    JointVector qm = q;
    qp[i] += h;
    qm[i] -= h;
    const Eigen::Isometry3d tp = kin.forward(qp);
    const Eigen::Isometry3d tm = kin.forward(qm);
    const auto col = static_cast<Eigen::Index>(i);
    j.block<3, 1>(0, col) = (tp.translation() - tm.translation()) / (2.0 * h);
    const Eigen::AngleAxisd aa(tp.linear() * tm.linear().transpose());
    j.block<3, 1>(3, col) = aa.axis() * aa.angle() / (2.0 * h);
  }
  return j;
}

TEST(RSM10_ArmKinematics, JacobianMatchesCentralFiniteDifference) {
  const ArmKinematics kin{kUr5DhTable};
  const JointVector poses[] = {
      {0.0, 0.0, 0.0, 0.0, 0.0, 0.0},    {kHalfPi, -kHalfPi, kHalfPi, 0.0, 0.0, 0.0},
      {0.3, -1.1, 1.7, -0.4, 0.9, -2.2}, {-2.5, -0.2, -1.3, 2.1, -1.4, 0.6},
      {1.0, -2.0, 0.5, 1.5, 0.25, 3.0},
  };
  for (const JointVector& q : poses) {
    const ArmKinematics::Jacobian ja = kin.jacobian(q);
    const ArmKinematics::Jacobian jn = numeric_jacobian(kin, q, 1e-6);
    EXPECT_LT((ja - jn).cwiseAbs().maxCoeff(), 1e-7) << "analytic\n" << ja << "\nnumeric\n" << jn;
  }
}

TEST(RSM10_ArmKinematics, AngularRowsAreJointAxes) {
  const ArmKinematics kin{kUr5DhTable};
  const ArmKinematics::Jacobian j = kin.jacobian(JointVector{});
  // Zero pose: z0 = +z, z1 = z2 = z3 = -y, z4 = -z, z5 = -y.
  expect_vec_near(j.block<3, 1>(3, 0), Eigen::Vector3d(0, 0, 1), 1e-12);
  expect_vec_near(j.block<3, 1>(3, 1), Eigen::Vector3d(0, -1, 0), 1e-12);
  expect_vec_near(j.block<3, 1>(3, 2), Eigen::Vector3d(0, -1, 0), 1e-12);
  expect_vec_near(j.block<3, 1>(3, 3), Eigen::Vector3d(0, -1, 0), 1e-12);
  expect_vec_near(j.block<3, 1>(3, 4), Eigen::Vector3d(0, 0, -1), 1e-12);
  expect_vec_near(j.block<3, 1>(3, 5), Eigen::Vector3d(0, -1, 0), 1e-12);
}

// Pure joint-1 rotation at the zero pose: the flange moves on a circle about the base z
// axis with radius r = horizontal distance of the flange from that axis,
//   r = sqrt(0.81725^2 + 0.19145^2) = sqrt(0.6678975625 + 0.0366531025)
//     = sqrt(0.704550665) = 0.839375... m,
// so |v| = omega · r; at omega = 0.2 rad/s: 167.875 mm/s.
TEST(RSM10_TcpSpeed, PureJointOneRotationIsOmegaTimesRadius) {
  const ArmKinematics kin{kUr5DhTable};
  const double r = std::sqrt(0.6678975625 + 0.0366531025);
  EXPECT_NEAR(r, 0.8393751, 1e-7);
  for (const double omega : {0.2, -0.2, 1.0, 0.05}) {
    const JointVector qd{omega, 0, 0, 0, 0, 0};
    EXPECT_NEAR(kin.tcp_speed_mm_s(JointVector{}, qd), std::abs(omega) * r * 1000.0, 1e-9);
  }
  // The joint-1 speed does not depend on joint 1's own angle.
  const JointVector q{1.234, 0, 0, 0, 0, 0};
  EXPECT_NEAR(kin.tcp_speed_mm_s(q, JointVector{0.2, 0, 0, 0, 0, 0}), 0.2 * r * 1000.0, 1e-9);
}

TEST(RSM10_TcpSpeed, ZeroVelocityGivesZeroSpeed) {
  const ArmKinematics kin{kUr5DhTable};
  EXPECT_EQ(kin.tcp_speed_mm_s(JointVector{0.3, -1.1, 1.7, -0.4, 0.9, -2.2}, JointVector{}), 0.0);
}

TEST(RSM10_TcpSpeed, Joint6RotationDoesNotMoveTheFlangeOrigin) {
  // The flange origin lies on the joint-6 axis: spinning joint 6 alone gives zero TCP speed.
  const ArmKinematics kin{kUr5DhTable};
  EXPECT_NEAR(kin.tcp_speed_mm_s(JointVector{0.3, -1.1, 1.7, -0.4, 0.9, -2.2}, JointVector{0, 0, 0, 0, 0, 3.0}), 0.0,
              1e-9);
}

TEST(RSM10_TcpSpeed, MatchesFiniteDifferenceOfFlangePosition) {
  const ArmKinematics kin{kUr5DhTable};
  const JointVector q{0.3, -1.1, 1.7, -0.4, 0.9, -2.2};
  const JointVector qd{0.1, -0.2, 0.15, 0.3, -0.25, 0.5};
  const double dt = 1e-6;
  JointVector qp = q;
  JointVector qm = q;
  for (std::size_t i = 0; i < kAxisCount; ++i) {
    qp[i] += qd[i] * dt;
    qm[i] -= qd[i] * dt;
  }
  const double numeric = (kin.forward(qp).translation() - kin.forward(qm).translation()).norm() / (2.0 * dt) * 1000.0;
  EXPECT_NEAR(kin.tcp_speed_mm_s(q, qd), numeric, 1e-5);
}

TEST(RSM10_TcpSpeed, T1LimitIsCrossedAtTheExpectedJointOneRate) {
  // 250 mm/s at the zero pose is reached at omega = 0.25 / r rad/s on joint 1.
  const ArmKinematics kin{kUr5DhTable};
  const double r = std::sqrt(0.704550665);
  const double omega_limit = 0.25 / r;
  EXPECT_LT(kin.tcp_speed_mm_s(JointVector{}, JointVector{omega_limit * 0.999, 0, 0, 0, 0, 0}), 250.0);
  EXPECT_GT(kin.tcp_speed_mm_s(JointVector{}, JointVector{omega_limit * 1.001, 0, 0, 0, 0, 0}), 250.0);
}

}  // namespace
