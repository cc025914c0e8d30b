// SPDX-License-Identifier: Apache-2.0
// Issue 29 item 4: Config::validate bounds every limit the safety functions depend on
// (design §9 "Configuration bounds"), with a reason code for each refusal.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "safestate/arm_kinematics.hpp"
#include "safestate/config.hpp"
#include "safestate/system_state_manager.hpp"
#include "ssm_test_support.hpp"

namespace {

using namespace safestate;  // NOLINT: test code

// Issue 29 item 4: the configuration can no longer defeat the limits. Each bound is
// tested at its edge: the last accepted value and the first refused one.
TEST(Issue29_Item4_ConfigBounds, T1LimitAboveTheIsoReducedSpeedIsRefused) {
  Config c;
  c.tool_offset_m = kFlangeTcp;
  c.t1_speed_limit_mm_s = 250;
  EXPECT_EQ(validate(c), ConfigError::None);
  c.t1_speed_limit_mm_s = 251;
  EXPECT_EQ(validate(c), ConfigError::T1LimitAboveReducedSpeed);
  c.t1_speed_limit_mm_s = 5000;  // the issue's reproduction
  EXPECT_EQ(validate(c), ConfigError::T1LimitAboveReducedSpeed);
}

TEST(Issue29_Item4_ConfigBounds, T2LimitLiesAboveT1AndWithinTheArmsReach) {
  Config c;
  c.tool_offset_m = kFlangeTcp;
  c.t2_speed_limit_mm_s = c.t1_speed_limit_mm_s;
  EXPECT_EQ(validate(c), ConfigError::T2LimitOutOfRange);
  c.t2_speed_limit_mm_s = c.t1_speed_limit_mm_s + 1;
  EXPECT_EQ(validate(c), ConfigError::None);
  c.t2_speed_limit_mm_s = kMaxT2SpeedLimitMmS;
  EXPECT_EQ(validate(c), ConfigError::None);
  c.t2_speed_limit_mm_s = kMaxT2SpeedLimitMmS + 1;
  EXPECT_EQ(validate(c), ConfigError::T2LimitOutOfRange);
  c.t2_speed_limit_mm_s = 0x7FFF'FFFF;
  EXPECT_EQ(validate(c), ConfigError::T2LimitOutOfRange);
}

TEST(Issue29_Item4_ConfigBounds, ZeroVelocityThresholdMustStayInsideTheStandstillWindowAtTheTool) {
  Config c;
  c.tool_offset_m = kFlangeTcp;
  c.zero_velocity_rad_s = 100.0;  // the issue's reproduction: every speed would read ZERO
  EXPECT_EQ(validate(c), ConfigError::ZeroVelocityAboveWindow);
  // The largest accepted threshold is the one whose worst-case TCP speed fills the window.
  const double per_rad = zero_class_tcp_bound_mm_s(c.dh, kFlangeTcp, 1.0);
  c.zero_velocity_rad_s = c.standstill_speed_window_mm_s / per_rad;
  EXPECT_EQ(validate(c), ConfigError::None);
  c.zero_velocity_rad_s *= 1.01;
  EXPECT_EQ(validate(c), ConfigError::ZeroVelocityAboveWindow);
  // A longer tool moves faster at the same joint speeds: the same threshold is refused.
  c.zero_velocity_rad_s = c.standstill_speed_window_mm_s / per_rad;
  c.tool_offset_m = std::array<double, 3>{0.0, 0.0, 0.3};
  EXPECT_EQ(validate(c), ConfigError::ZeroVelocityAboveWindow);
}

TEST(Issue29_Item4_ConfigBounds, StandstillWindowMustLieBelowTheT1Limit) {
  Config c;
  c.tool_offset_m = kFlangeTcp;
  c.standstill_speed_window_mm_s = 0.0;
  EXPECT_EQ(validate(c), ConfigError::StandstillWindowOutOfRange);
  c.standstill_speed_window_mm_s = static_cast<double>(c.t1_speed_limit_mm_s);
  EXPECT_EQ(validate(c), ConfigError::StandstillWindowOutOfRange);
  c.standstill_speed_window_mm_s = std::nan("");
  EXPECT_EQ(validate(c), ConfigError::StandstillWindowOutOfRange);
  c.standstill_speed_window_mm_s = 249.0;
  EXPECT_EQ(validate(c), ConfigError::None);
}

// The bound is a true upper bound: no pose and no joint speeds within the threshold give a
// faster TCP than zero_class_tcp_bound_mm_s (checked against the kinematics on a grid).
TEST(Issue29_Item4_ConfigBounds, ZeroClassBoundCoversEveryPoseOnAGrid) {
  const std::array<double, 3> tool{0.05, -0.02, 0.3};
  const ArmKinematics arm(kUr5DhTable, tool);
  const double w = 0.01;
  const double bound = zero_class_tcp_bound_mm_s(kUr5DhTable, tool, w);
  double worst = 0.0;
  for (int k = 0; k < 729; ++k) {
    JointVector q{};
    int r = k;
    for (std::size_t j = 1; j < 4; ++j) {  // joints 2-4 set the lever arms; 1, 5, 6 less so
      q[j] = -3.0 + 3.0 * (r % 9) / 4.0;
      r /= 9;
    }
    for (int signs = 0; signs < 64; ++signs) {
      JointVector qd{};
      for (std::size_t j = 0; j < 6; ++j) qd[j] = ((signs >> j) & 1) != 0 ? w : -w;
      worst = std::max(worst, arm.tcp_speed_mm_s(q, qd));
    }
  }
  EXPECT_GT(worst, 0.3 * bound);  // the grid reaches the bound's order of magnitude
  EXPECT_LE(worst, bound);
}

TEST(Issue29_Item4_ConfigBounds, ToolOffsetMustBeStated) {
  Config c;
  EXPECT_EQ(validate(c), ConfigError::ToolOffsetNotGiven);
  SystemStateManager m(c);  // an invalid Config fails the BOOT self-test (C02)
  ScanInputs in = ssm_test::healthy();
  (void)m.cycle(in);
  EXPECT_EQ(m.state(), StateId::ErrorLockout);
  EXPECT_EQ(m.status().fault_code, FaultCode::SelfTestFailed);
  c.tool_offset_m = std::array<double, 3>{0.0, 0.0, 0.3};
  EXPECT_EQ(validate(c), ConfigError::None);
  c.tool_offset_m = std::array<double, 3>{0.0, std::nan(""), 0.3};
  EXPECT_EQ(validate(c), ConfigError::DhTableNotFinite);
}

}  // namespace
