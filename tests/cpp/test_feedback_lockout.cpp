// SPDX-License-Identifier: Apache-2.0
// UCA-RSM-13 (issue 29 item 10): the contactor's auxiliary contact and the brakes' feedback
// are inputs of the manager, monitored every cycle against the output the previous cycle
// wrote; a disagreement beyond feedback_allowed_cycles is a Cat 0 lockout (C30).
#include <gtest/gtest.h>

#include <cstdint>

#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT: test code

Config short_feedback(std::uint32_t allowed) {
  Config c = flange_config();
  c.feedback_allowed_cycles = allowed;
  return c;
}

// A welded contactor: commanded open in IDLE, its auxiliary contact still reports closed.
// The (allowed + 1)-th cycle in a row locks out with CONTACTOR_FEEDBACK, Cat 0; a Servo-on
// is refused from then on (the issue: "a welded contactor goes undetected").
// req: RSM-03 RSM-07
TEST(UCA_RSM_13_Feedback, AWeldedContactorLocksOutAfterItsSwitchingTime) {
  Rig r(short_feedback(3));
  r.boot();
  r.ideal_feedback = false;
  r.in.contactor_feedback_closed = true;  // welded
  for (std::uint32_t n = 1; n <= 3; ++n) {
    r.cycle();
    EXPECT_EQ(r.state(), StateId::Idle) << n;
    EXPECT_EQ(r.st().contactor_fb_cycles, n);
  }
  r.cycle();
  EXPECT_EQ(r.cycle_row(), "C30");
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::ContactorFeedback);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_FALSE(r.out.contactor_closed);
  EXPECT_FALSE(r.out.drive_enable);
  EXPECT_FALSE(r.out.brake_release);
  // Latched: the contact reporting open again does not clear it.
  r.in.contactor_feedback_closed = false;
  r.cycles(3);
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::LockedOut));
}

// A contactor that does not pull in, and brakes that do not release: the powered side.
// req: RSM-03 RSM-07
TEST(UCA_RSM_13_Feedback, AContactorThatDoesNotCloseOrBrakesThatDoNotReleaseLockOut) {
  for (const bool brake : {false, true}) {
    Rig r(short_feedback(2));
    r.to_operational(SelectorReading::Auto);
    r.ideal_feedback = false;
    r.in.contactor_feedback_closed = brake;  // contactor case: its contact stays open
    r.in.brake_feedback_released = !brake;   // brake case: the brakes stay applied
    r.cycles(2);
    EXPECT_EQ(r.state(), StateId::AutoIdle) << brake;
    r.cycle();
    EXPECT_EQ(r.state(), StateId::ErrorLockout) << brake;
    EXPECT_EQ(r.st().fault_code, brake ? FaultCode::BrakeFeedback : FaultCode::ContactorFeedback);
    EXPECT_FALSE(r.out.contactor_closed);
  }
}

// A device within its switching time is not a fault: the feedback may lag by up to
// feedback_allowed_cycles cycles after every change of the command, and agreement restarts
// the count.
// req: RSM-03
TEST(UCA_RSM_13_Feedback, AFeedbackWithinItsSwitchingTimeIsNotAFault) {
  Rig r(short_feedback(2));
  r.boot(SelectorReading::Auto);
  r.ideal_feedback = false;
  r.in.contactor_feedback_closed = false;
  r.in.brake_feedback_released = false;
  ASSERT_EQ(r.command(Command::servo_on()), CommandResult::accepted());  // contactor commanded closed
  r.cycles(2);                                                           // the contact lags two cycles
  EXPECT_EQ(r.st().contactor_fb_cycles, 2U);
  r.in.contactor_feedback_closed = true;
  r.cycle();
  EXPECT_EQ(r.st().contactor_fb_cycles, 0U);
  EXPECT_EQ(r.st().fault_code, FaultCode::None);
  EXPECT_TRUE(r.out.contactor_closed);
}

// An E-stop in the cycle the feedback fault matures keeps the lockout (C30 precedes C06).
// req: RSM-03 RSM-04
TEST(UCA_RSM_13_Feedback, AnEstopInTheSameCycleKeepsTheFeedbackLockout) {
  Rig r(short_feedback(0));
  r.boot();
  r.ideal_feedback = false;
  r.in.contactor_feedback_closed = true;
  r.in.estop_closed = {false, false};
  r.cycle();
  EXPECT_EQ(r.st().fault_code, FaultCode::ContactorFeedback);
  EXPECT_NE(r.state(), StateId::EstopActive);
}

TEST(UCA_RSM_13_Feedback, TheSwitchingTimeIsBounded) {
  Config c = flange_config();
  c.feedback_allowed_cycles = kMaxFeedbackCycles;
  EXPECT_EQ(validate(c), ConfigError::None);
  c.feedback_allowed_cycles = kMaxFeedbackCycles + 1U;
  EXPECT_EQ(validate(c), ConfigError::FeedbackTimeTooLarge);
}

}  // namespace
