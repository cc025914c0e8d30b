// SPDX-License-Identifier: Apache-2.0
// Issue 29 item 5: T2 has limits. The jog speed request is bounded by the configured T2
// limit in the command validation (K26), in every manual mode.
#include <gtest/gtest.h>

#include <cstdint>

#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT: test code

TEST(Issue29_Item5_T2Limits, AJogRequestAboveTheT2LimitIsRejectedAndChangesNothing) {
  Rig r;
  r.to_operational(SelectorReading::T2);
  ASSERT_EQ(r.state(), StateId::ManualIdle);
  const StatusRecord before = r.st();
  // The issue's reproduction: 2^31 - 1 mm/s was accepted and output.
  EXPECT_EQ(r.command(Command::jog_start(1, 1, 0x7FFF'FFFF)), CommandResult::rejected(RejectReason::InvalidArgument));
  EXPECT_EQ(r.command_row(), "K26");
  EXPECT_EQ(without_command_fields(r.st()), without_command_fields(before));
  EXPECT_EQ(r.out.commanded_speed_mm_s, 0);
  const std::int32_t limit = r.m.config().t2_speed_limit_mm_s;
  EXPECT_EQ(r.command(Command::jog_start(1, 1, limit + 1)), CommandResult::rejected(RejectReason::InvalidArgument));
  EXPECT_EQ(r.command(Command::jog_start(1, 1, limit)), CommandResult::accepted());
  EXPECT_EQ(r.out.commanded_speed_mm_s, limit);
}

TEST(Issue29_Item5_T2Limits, TheConfiguredT2LimitIsTheBound) {
  Config c = flange_config();
  c.t2_speed_limit_mm_s = 600;
  Rig r(c);
  r.to_operational(SelectorReading::T2);
  EXPECT_EQ(r.command(Command::jog_start(3, -1, 601)), CommandResult::rejected(RejectReason::InvalidArgument));
  EXPECT_EQ(r.command(Command::jog_start(3, -1, 600)), CommandResult::accepted());
  EXPECT_EQ(r.out.commanded_speed_mm_s, 600);
}

TEST(Issue29_Item5_T2Limits, InT1ARequestUpToTheT2LimitIsClampedAndAboveItRejected) {
  Rig r;
  r.to_operational(SelectorReading::T1);
  const std::int32_t t2 = r.m.config().t2_speed_limit_mm_s;
  EXPECT_EQ(r.command(Command::jog_start(1, 1, t2 + 1)), CommandResult::rejected(RejectReason::InvalidArgument));
  EXPECT_EQ(r.command(Command::jog_start(1, 1, t2)), CommandResult::accepted());
  EXPECT_EQ(r.out.commanded_speed_mm_s, r.m.config().t1_speed_limit_mm_s);  // K29's clamp
}

}  // namespace
