// SPDX-License-Identifier: Apache-2.0
// UCA-RSM-14 (only the jogged axis is commanded to move) and UCA-RSM-15 (no monitoring
// lockout without its cause) of the design page's hazard analysis (§13): the C++ driven the
// way the model's properties UCA_JOG_AXIS, UCA_FEEDBACK_CAUSE and UCA_DISCREPANCY_CAUSE say,
// asserted over the outputs and the status record.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>

#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT: test code

bool in_motion(AxisState a) {
  return a == AxisState::ContinuousMotion || a == AxisState::SynchronizedMotion || a == AxisState::DiscreteMotion ||
         a == AxisState::Homing;
}

/// Every axis but `jogged` (1-based) out of the PLCopen motion states; `jogged` in
/// ContinuousMotion.
void expect_only_axis_moves(const ScanOutputs& out, std::int32_t jogged) {
  for (std::size_t i = 0; i < out.axes.size(); ++i) {
    if (static_cast<std::int32_t>(i) + 1 == jogged) {
      EXPECT_EQ(out.axes[i], AxisState::ContinuousMotion) << "jogged axis " << jogged;
    } else {
      EXPECT_FALSE(in_motion(out.axes[i])) << "axis " << i + 1 << " moves while axis " << jogged << " is jogged";
    }
  }
}

// ---------------------------------------------------------------- UCA-RSM-14: the jogged axis

// UCA-RSM-14: a jog on axis a, in T1 and in T2, commands axis a alone into motion, in the
// cycle that accepts the JOG_START and in every cycle of the jog.
// req: RSM-09 RSM-17
TEST(UCA_RSM_14_JogAxis, OnlyTheJoggedAxisIsCommandedToMoveOnEveryAxisInT1AndT2) {
  for (const SelectorReading mode : {SelectorReading::T1, SelectorReading::T2}) {
    for (std::int32_t axis = 1; axis <= static_cast<std::int32_t>(kAxisCount); ++axis) {
      Rig r;
      r.to_operational(mode);
      ASSERT_EQ(r.command(Command::jog_start(axis, -1, 100)), CommandResult::accepted()) << axis;
      EXPECT_GT(r.out.commanded_speed_mm_s, 0);
      expect_only_axis_moves(r.out, axis);
      r.in.qd = kSlow;
      for (int n = 0; n < 5; ++n) {
        r.cycle();
        ASSERT_EQ(r.state(), StateId::ManualJogging) << to_string(mode) << " axis " << axis;
        expect_only_axis_moves(r.out, axis);
      }
    }
  }
}

// UCA-RSM-14: a jog paused (Cat 2, HOLD) and resumed moves the axis the JOG_START named,
// and no other.
// req: RSM-09 RSM-11 RSM-17
TEST(UCA_RSM_14_JogAxis, AResumedJogMovesTheAxisItNamedAndNoOther) {
  Rig r;
  r.to_jogging(SelectorReading::T1);  // axis 2
  ASSERT_EQ(r.command(Command::pause()), CommandResult::accepted());
  r.in.qd = kRest;
  r.cycle();
  ASSERT_EQ(r.state(), StateId::Hold);
  for (const AxisState a : r.out.axes) EXPECT_FALSE(in_motion(a));
  ASSERT_EQ(r.command(Command::resume()), CommandResult::accepted());
  ASSERT_EQ(r.state(), StateId::ManualJogging);
  expect_only_axis_moves(r.out, 2);
}

// UCA-RSM-14: a JOG_START naming an axis the robot does not have (0, 7, negative) is
// rejected with INVALID_ARGUMENT and commands no speed and no axis into motion.
// req: RSM-09 RSM-13 RSM-17
TEST(UCA_RSM_14_JogAxis, AJogForAnAxisTheRobotDoesNotHaveIsRejected) {
  for (const std::int32_t axis : {0, static_cast<std::int32_t>(kAxisCount) + 1, -1}) {
    Rig r;
    r.to_operational(SelectorReading::T1);
    EXPECT_EQ(r.command(Command::jog_start(axis, 1, 100)), CommandResult::rejected(RejectReason::InvalidArgument))
        << axis;
    EXPECT_EQ(r.state(), StateId::ManualIdle);
    EXPECT_EQ(r.out.commanded_speed_mm_s, 0);
    for (const AxisState a : r.out.axes) EXPECT_FALSE(in_motion(a)) << axis;
  }
}

// ---------------------------------------------------------------- UCA-RSM-15: lockout causes

// UCA-RSM-15: a contactor whose auxiliary contact lags one cycle behind its command (within
// a switching time of 1 cycle) while the command changes twice in a row (Servo-on, then the
// safeguard opens in ARMING: power removed at once) disagrees in two consecutive cycles, but
// under two commands: no lockout. The count restarts at the change (the model's mutant that
// kept counting locked out here).
// req: RSM-03 RSM-07
TEST(UCA_RSM_15_LockoutCause, AContactorLaggingAcrossTwoQuickCommandChangesIsNotAFault) {
  Config c = flange_config();
  c.feedback_allowed_cycles = 1;
  Rig r(c);
  r.boot(SelectorReading::Auto);
  r.ideal_feedback = false;
  r.in.contactor_feedback_closed = false;
  r.in.brake_feedback_released = false;
  r.plant.servo_ready = false;
  ASSERT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
  ASSERT_TRUE(r.out.contactor_closed);
  // Commanded closed, the contact still open; the safeguard opens: Cat 1 from ARMING, IDLE.
  r.in.safeguard_closed = {true, false};
  r.cycle();
  ASSERT_EQ(r.state(), StateId::Idle);
  EXPECT_EQ(r.st().contactor_fb_cycles, 1U);
  EXPECT_FALSE(r.out.contactor_closed);
  // Commanded open now, the contact pulls in one cycle late: a disagreement under a new command.
  r.in.safeguard_closed = {true, true};
  r.in.contactor_feedback_closed = true;
  r.cycle();
  EXPECT_EQ(r.st().contactor_fb_cycles, 1U);
  EXPECT_EQ(r.st().fault_code, FaultCode::None);
  EXPECT_EQ(r.state(), StateId::Idle);
  // It drops out one cycle later: agreement.
  r.in.contactor_feedback_closed = false;
  r.cycle();
  EXPECT_EQ(r.st().contactor_fb_cycles, 0U);
  EXPECT_EQ(r.st().fault_code, FaultCode::None);
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
}

// UCA-RSM-15: the same contact disagreeing for allowed + 1 cycles under one command is the
// lockout, and not a cycle earlier.
// req: RSM-03 RSM-07
TEST(UCA_RSM_15_LockoutCause, AFeedbackLockoutComesExactlyAfterItsSwitchingTimeUnderOneCommand) {
  for (const std::uint32_t allowed : {0U, 1U, 4U}) {
    Config c = flange_config();
    c.feedback_allowed_cycles = allowed;
    Rig r(c);
    r.boot(SelectorReading::Auto);
    r.ideal_feedback = false;
    r.in.contactor_feedback_closed = true;  // commanded open
    r.in.brake_feedback_released = false;
    for (std::uint32_t n = 1; n <= allowed; ++n) {
      r.cycle();
      ASSERT_EQ(r.st().fault_code, FaultCode::None) << allowed << " cycle " << n;
    }
    r.cycle();
    EXPECT_EQ(r.st().fault_code, FaultCode::ContactorFeedback) << allowed;
  }
}

// UCA-RSM-15: an E-stop channel disagreement from the very first cycle locks out after
// D + 1 cycles, not earlier; one shorter than D + 1 cycles, agreement, and another one
// shorter than D + 1 cycles is no fault (the count restarts).
// req: RSM-04 RSM-12
TEST(UCA_RSM_15_LockoutCause, ADiscrepancyLockoutOnlyAfterDPlusOneCyclesOfDisagreement) {
  Config c = flange_config();
  c.discrepancy_cycles = 3;
  Rig r(c);
  r.in = healthy(SelectorReading::Auto);
  r.in.estop_closed = {true, false};
  for (std::uint32_t n = 1; n <= c.discrepancy_cycles; ++n) {
    r.cycle();
    ASSERT_EQ(r.st().fault_code, FaultCode::None) << "cycle " << n;
  }
  r.cycle();
  EXPECT_EQ(r.st().fault_code, FaultCode::DiscrepancyEstop);

  Rig s(c);
  s.boot(SelectorReading::Auto);
  for (int episode = 0; episode < 3; ++episode) {
    s.in.estop_closed = {true, false};
    s.cycles(c.discrepancy_cycles);
    EXPECT_EQ(s.st().fault_code, FaultCode::None) << episode;
    s.in.estop_closed = {false, false};
    s.cycle();
  }
  EXPECT_EQ(s.st().fault_code, FaultCode::None);
  EXPECT_EQ(s.state(), StateId::EstopActive);
}

}  // namespace
