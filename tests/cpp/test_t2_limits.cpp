// SPDX-License-Identifier: Apache-2.0
// Issue 29 item 5: T2 has limits. The jog speed request is bounded by the configured T2
// limit in the command validation (K26), in every manual mode.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "safestate/speed_monitor.hpp"
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

// The issue's reproduction was a Servo-on accepted ten minutes after the confirmation.
// With a timeout of T cycles, the Servo-on of the T-th cycle after K35's is accepted and the
// one of the (T+1)-th is refused.
TEST(Issue29_Item5_T2Limits, TheT2ConfirmationExpiresAfterItsConfiguredTime) {
  for (const std::uint32_t wait : {0U, 1U}) {
    Config c = flange_config();
    c.t2_confirm_timeout_cycles = 5;
    Rig r(c);
    r.boot(SelectorReading::T2);
    ASSERT_EQ(r.command(Command::t2_confirm()), CommandResult::accepted());  // K35, cycle n
    r.cycles(4 + wait);                                                      // n+1 .. n+4(+1)
    EXPECT_EQ(r.st().state_cycles, 4U + wait);                 // cleared by the next cycle's C22 once it reaches 5
    const CommandResult got = r.command(Command::servo_on());  // popped in cycle n+5(+1)
    if (wait == 0U) {
      EXPECT_EQ(got, CommandResult::accepted());
      EXPECT_EQ(r.state(), StateId::Arming);
    } else {
      EXPECT_EQ(got, CommandResult::rejected(RejectReason::T2NotConfirmed));
      EXPECT_EQ(r.command_row(), "K11");
      EXPECT_EQ(r.state(), StateId::Idle);
    }
  }
}

TEST(Issue29_Item5_T2Limits, ConfirmingAgainRestartsTheTimeAndLeavingT2ClearsIt) {
  Config c = flange_config();
  c.t2_confirm_timeout_cycles = 3;
  Rig r(c);
  r.boot(SelectorReading::T2);
  ASSERT_EQ(r.command(Command::t2_confirm()), CommandResult::accepted());
  r.cycles(2);
  EXPECT_EQ(r.st().state_cycles, 2U);
  ASSERT_EQ(r.command(Command::t2_confirm()), CommandResult::accepted());
  EXPECT_EQ(r.st().state_cycles, 0U);
  r.cycles(2);
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
  Rig off(c);
  off.boot(SelectorReading::T2);
  ASSERT_EQ(off.command(Command::t2_confirm()), CommandResult::accepted());
  off.in.selector = contacts(SelectorReading::T1);
  off.cycle();
  EXPECT_FALSE(off.st().t2_confirmed);
  EXPECT_EQ(off.st().state_cycles, 0U);
}

TEST(Issue29_Item5_T2Limits, AZeroConfirmationTimeIsRefused) {
  Config c = flange_config();
  c.t2_confirm_timeout_cycles = 0;
  EXPECT_EQ(validate(c), ConfigError::T2ConfirmTimeoutOutOfRange);
  c.t2_confirm_timeout_cycles = kMaxTimerCycles + 1U;
  EXPECT_EQ(validate(c), ConfigError::T2ConfirmTimeoutOutOfRange);
}

// ---------------------------------------------------------------- measured speed in T2

// UCA-RSM-12 (issue 29 item 5): the reproduction measured 12,845 mm/s in a T2 jog with no
// fault. A TCP speed above t2_speed_limit_mm_s in a T2 session removes power in the cycle
// that measures it (Cat 0, C29) and locks out with T2_OVERSPEED.
// req: RSM-10 RSM-03
TEST(UCA_RSM_12_T2Overspeed, MeasuredSpeedAboveTheT2LimitCutsPowerInTheSameCycle) {
  Rig r;
  r.to_jogging(SelectorReading::T2, 1000);
  r.in.qd = JointVector{20.0, 0, 0, 0, 0, 0};  // ~12,800 mm/s at this pose
  r.cycle();
  EXPECT_EQ(r.cycle_row(), "C29");
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::T2Overspeed);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_FALSE(r.out.contactor_closed);
  EXPECT_FALSE(r.out.drive_enable);
  EXPECT_FALSE(r.out.brake_release);
  EXPECT_EQ(r.command(Command::reset()), CommandResult::rejected(RejectReason::LockedOut));
}

// The bound is the configured limit: exactly at it is allowed, just above it is not.
// req: RSM-10
TEST(UCA_RSM_12_T2Overspeed, TheConfiguredT2LimitIsTheBoundOfTheMeasuredSpeed) {
  for (const bool above : {false, true}) {
    Config c = flange_config();
    c.t2_speed_limit_mm_s = 600;
    Rig r(c);
    r.to_jogging(SelectorReading::T2, 600);
    const SpeedMonitor mon{c};
    double w = 600.0 / mon.tcp_speed_mm_s(kPose, JointVector{1.0, 0, 0, 0, 0, 0});
    for (int i = 0; i < 64 && mon.tcp_speed_mm_s(kPose, JointVector{w, 0, 0, 0, 0, 0}) != 600.0; ++i) {
      w = std::nextafter(w, mon.tcp_speed_mm_s(kPose, JointVector{w, 0, 0, 0, 0, 0}) < 600.0 ? 1e9 : 0.0);
    }
    ASSERT_EQ(mon.tcp_speed_mm_s(kPose, JointVector{w, 0, 0, 0, 0, 0}), 600.0);
    r.in.qd = JointVector{above ? w * (1 + 1e-9) : w, 0, 0, 0, 0, 0};
    r.cycles(3);
    EXPECT_EQ(r.state(), above ? StateId::ErrorLockout : StateId::ManualJogging) << above;
    EXPECT_EQ(r.st().fault_code, above ? FaultCode::T2Overspeed : FaultCode::None) << above;
  }
}

// Every powered state of a T2 session is supervised, also while the jog stops (STOPPING)
// and in HOLD, and an E-stop in the same cycle does not make the overspeed forgotten.
// req: RSM-10 RSM-03 RSM-04
TEST(UCA_RSM_12_T2Overspeed, EveryPoweredT2StateIsSupervisedAndTheLockoutSurvivesAnEstop) {
  for (const bool estop : {false, true}) {
    Rig r;
    r.to_jogging(SelectorReading::T2, 1000);
    ASSERT_EQ(r.command(Command::pause()), CommandResult::accepted());
    ASSERT_EQ(r.state(), StateId::Stopping);
    r.in.qd = kFast;
    if (estop) r.in.estop_closed = {true, false};
    r.cycle();
    EXPECT_EQ(r.st().fault_code, FaultCode::T2Overspeed) << estop;
    EXPECT_FALSE(r.out.contactor_closed);
  }
  Rig idle;
  idle.to_operational(SelectorReading::T2);
  idle.in.qd = kFast;
  idle.cycle();
  EXPECT_EQ(idle.st().fault_code, FaultCode::T2Overspeed);  // C29 before C25's standstill code
}

// Between the two limits a T2 session keeps running; in T1 any speed above T1's limit,
// OVER_T2 included, is C10's T1_OVERSPEED.
// req: RSM-10
TEST(UCA_RSM_12_T2Overspeed, BetweenTheLimitsT2RunsAndAboveBothT1LocksOutAsT1) {
  Rig t2;
  t2.to_jogging(SelectorReading::T2, 1000);
  t2.in.qd = kMedium;
  t2.cycles(5);
  EXPECT_EQ(t2.state(), StateId::ManualJogging);
  Rig t1;
  t1.to_jogging(SelectorReading::T1);
  t1.in.qd = kFast;
  t1.cycle();
  EXPECT_EQ(t1.st().fault_code, FaultCode::T1Overspeed);
  EXPECT_EQ(t1.cycle_row(), "C10");
}

}  // namespace
