// SPDX-License-Identifier: Apache-2.0
// The reproductions of issue 29 (an assessor's run against the hazards), one test per unsafe
// control action of the design page's hazard analysis (UCA-RSM-nn): each drives the C++ the
// way the reproduction did and asserts the safe outcome over the outputs.
#include <gtest/gtest.h>

#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT: test code

/// Joint 4 turning at 3 rad/s while the jogged axis (2) stops: MOVING at every pose.
constexpr JointVector kOtherAxisTurning{0.0, 0.0, 0.0, 3.0, 0.0, 0.0};

void expect_unpowered(const ScanOutputs& out) {
  EXPECT_FALSE(out.contactor_closed);
  EXPECT_FALSE(out.drive_enable);
  EXPECT_FALSE(out.brake_release);
}

// ---------------------------------------------------------------- item 1: stop after JOG_STOP

// UCA-RSM-07: after JOG_STOP the arm keeps moving (T1 at 96 mm/s, T2 at 1,284 mm/s in the
// reproduction): the stop is a Cat 2 ramp watched by the stop timer, so power is cut and the
// manager locks out max_stop_cycles + 1 cycles after the JOG_STOP at the latest.
// req: RSM-11 RSM-09
TEST(UCA_RSM_07_JogStop, ArmStillMovingAfterTheStopTimeLocksOutInT1AndT2) {
  for (const SelectorReading mode : {SelectorReading::T1, SelectorReading::T2}) {
    Rig r;
    r.to_jogging(mode);
    r.in.qd = mode == SelectorReading::T2 ? kMedium : kSlow;  // above T1's limit is C10's, T2's C29's
    ASSERT_EQ(r.command(Command::jog_stop()), CommandResult::accepted());
    EXPECT_TRUE(r.out.ramp_down_request) << to_string(mode);
    EXPECT_EQ(r.out.commanded_speed_mm_s, 0);
    std::uint32_t n = 1;
    while (r.out.contactor_closed && n <= r.m.config().max_stop_cycles + 1) {
      r.cycle();
      ++n;
    }
    expect_unpowered(r.out);
    EXPECT_EQ(r.st().fault_code, FaultCode::StopTimeout) << to_string(mode);
    EXPECT_EQ(n, r.m.config().max_stop_cycles + 2) << to_string(mode);
  }
}

// UCA-RSM-07: another axis turning at 3 rad/s while the jogged axis stops is seen too: in
// T2 the stop never completes (stop timer), in T1 it is above the TCP limit at once (C10).
// req: RSM-11 RSM-09
TEST(UCA_RSM_07_JogStop, AnotherAxisTurningDuringTheJogStopIsNotMissed) {
  Rig r;
  r.to_jogging(SelectorReading::T2);
  ASSERT_EQ(r.command(Command::jog_stop()), CommandResult::accepted());
  r.in.qd = kOtherAxisTurning;
  r.cycles(r.m.config().max_stop_cycles + 1);
  expect_unpowered(r.out);
  EXPECT_EQ(r.st().fault_code, FaultCode::StopTimeout);
  Rig t1;
  t1.to_jogging(SelectorReading::T1);
  ASSERT_EQ(t1.command(Command::jog_stop()), CommandResult::accepted());
  t1.in.qd = kOtherAxisTurning;
  t1.cycle();
  expect_unpowered(t1.out);
  EXPECT_EQ(t1.st().fault_code, FaultCode::T1Overspeed);
}

// UCA-RSM-07: once the jog stop reached standstill (MANUAL_IDLE), any motion is a violation.
// req: RSM-11 RSM-09
TEST(UCA_RSM_07_JogStop, MotionAfterTheJogStopReachedStandstillLocksOutAtOnce) {
  Rig r;
  r.to_jogging(SelectorReading::T2);
  ASSERT_EQ(r.command(Command::jog_stop()), CommandResult::accepted());
  r.in.qd = kRest;
  r.cycle();
  ASSERT_EQ(r.state(), StateId::ManualIdle);
  r.in.qd = kOtherAxisTurning;
  r.cycle();
  expect_unpowered(r.out);
  EXPECT_EQ(r.st().fault_code, FaultCode::StandstillViolation);
}

// ---------------------------------------------------------------- item 2: brake release order

// UCA-RSM-02: contactor and drive enable in ARMING, the brakes only once servo_ready is read.
// req: RSM-07
TEST(UCA_RSM_02_BrakeOrder, BrakesStayEngagedUntilTheDrivesReportReady) {
  Rig r;
  r.boot(SelectorReading::Auto);
  r.plant.servo_ready = false;
  ASSERT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
  for (std::uint32_t i = 0; i < r.m.config().arming_timeout_cycles; ++i) {
    ASSERT_EQ(r.state(), StateId::Arming);
    EXPECT_TRUE(r.out.contactor_closed);
    EXPECT_TRUE(r.out.drive_enable);
    EXPECT_FALSE(r.out.brake_release) << "cycle " << i;
    r.cycle();
  }
  r.plant.servo_ready = true;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::AutoIdle);
  EXPECT_TRUE(r.out.brake_release);
}

// UCA-RSM-02: a stop trigger while arming removes power at once; the brakes never opened.
// req: RSM-07
TEST(UCA_RSM_02_BrakeOrder, AStopTriggerInArmingRemovesPowerWithoutReleasingTheBrakes) {
  Rig r;
  r.boot(SelectorReading::Auto);
  r.plant.servo_ready = false;
  ASSERT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
  r.in.safeguard_closed = {true, false};
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);
  expect_unpowered(r.out);
}

// ---------------------------------------------------------------- item 3: servo_ready lost

// UCA-RSM-03: servo_ready lost in AUTO_RUNNING, AUTO_IDLE, MANUAL_IDLE, MANUAL_JOGGING, HOLD
// and STOPPING (the reproduction held it false for 5,000 cycles): Cat 0 in that cycle, lockout.
// req: RSM-07 RSM-03
TEST(UCA_RSM_03_ServoReadyLost, InEveryStateWithTheBrakesReleasedLocksOutInTheSameCycle) {
  std::vector<std::pair<const char*, void (*)(Rig&)>> setups{
      {"AUTO_IDLE", [](Rig& r) { r.to_operational(SelectorReading::Auto); }},
      {"AUTO_RUNNING", [](Rig& r) { r.to_auto_running(); }},
      {"MANUAL_IDLE", [](Rig& r) { r.to_operational(SelectorReading::T1); }},
      {"MANUAL_JOGGING", [](Rig& r) { r.to_jogging(SelectorReading::T2); }},
      {"HOLD", [](Rig& r) { r.to_hold(); }},
      {"STOPPING",
       [](Rig& r) {
         r.to_auto_running();
         ASSERT_EQ(r.command(Command::servo_off()), CommandResult::accepted());
       }},
  };
  for (const auto& [name, setup] : setups) {
    Rig r;
    setup(r);
    ASSERT_TRUE(r.out.brake_release) << name;
    r.plant.servo_ready = false;
    r.cycle();
    expect_unpowered(r.out);
    EXPECT_EQ(r.st().fault_code, FaultCode::ServoReadyLost) << name;
    r.plant.servo_ready = true;
    EXPECT_EQ(r.command(Command::reset()), CommandResult::rejected(RejectReason::LockedOut)) << name;
  }
}

// ---------------------------------------------------------------- item 6: PANIC -> MIDDLE

// UCA-RSM-05 (ISO 10218-1 5.8.3): after a panic stop, the device back in MIDDLE without
// passing RELEASED does not enable: Servo-on is refused until it was released.
// req: RSM-09 RSM-06 INV-ENABLE
TEST(UCA_RSM_05_PanicRearm, PanicThenMiddleDoesNotReEnableUntilReleased) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  r.in.enabling = {EnablePosition::Panic, EnablePosition::Panic};
  r.in.qd = kRest;
  r.cycle();
  ASSERT_EQ(r.cycle_row(), "C11");
  expect_unpowered(r.out);
  r.in.enabling = {EnablePosition::Middle, EnablePosition::Middle};
  r.cycle();
  EXPECT_TRUE(r.st().enable_release_required);
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::EnableNotMiddle));
  EXPECT_EQ(r.command_row(), "K39");
  expect_unpowered(r.out);
  r.in.enabling = {EnablePosition::Released, EnablePosition::Middle};  // one channel is not enough
  r.cycle();
  r.in.enabling = {EnablePosition::Middle, EnablePosition::Middle};
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::EnableNotMiddle));
  r.in.enabling = {EnablePosition::Released, EnablePosition::Released};
  r.cycle();
  EXPECT_FALSE(r.st().enable_release_required);
  r.in.enabling = {EnablePosition::Middle, EnablePosition::Middle};
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
}

// UCA-RSM-05: a one-channel PANIC while unpowered counts as well.
// req: RSM-09 RSM-06 INV-ENABLE
TEST(UCA_RSM_05_PanicRearm, OneChannelPanicInIdleAlsoNeedsARelease) {
  Rig r;
  r.boot(SelectorReading::T2);
  ASSERT_EQ(r.command(Command::t2_confirm()), CommandResult::accepted());
  r.in.enabling = {EnablePosition::Middle, EnablePosition::Panic};
  r.cycle();
  r.in.enabling = {EnablePosition::Middle, EnablePosition::Middle};
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::EnableNotMiddle));
  EXPECT_EQ(r.command_row(), "K39");
}

// ---------------------------------------------------------------- item 7: simultaneous events

// UCA-RSM-06: an E-stop and a drive fault in the same cycle: power off and the lockout kept;
// Reset after both cleared is refused (LOCKED_OUT), not accepted.
// req: RSM-07 RSM-10 RSM-04
TEST(UCA_RSM_06_SimultaneousEvents, EstopWithADriveFaultKeepsTheLockout) {
  Rig r;
  r.to_auto_running();
  r.in.estop_closed = {false, false};
  r.plant.drive_fault = true;
  r.cycle();
  expect_unpowered(r.out);
  EXPECT_EQ(r.st().fault_code, FaultCode::DriveFault);
  r.in.estop_closed = {true, true};
  r.plant.drive_fault = false;
  r.cycles(3);
  EXPECT_EQ(r.command(Command::reset()), CommandResult::rejected(RejectReason::LockedOut));
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
}

// UCA-RSM-06: an E-stop and a T1 overspeed in the same cycle: the overspeed is not forgotten.
// req: RSM-07 RSM-10 RSM-04
TEST(UCA_RSM_06_SimultaneousEvents, EstopWithAT1OverspeedKeepsTheLockout) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  r.in.estop_closed = {true, false};
  r.in.qd = kFast;
  r.cycle();
  expect_unpowered(r.out);
  EXPECT_EQ(r.st().fault_code, FaultCode::T1Overspeed);
}

// UCA-RSM-06: an E-stop in the cycle the drives stop reporting ready keeps that lockout too.
// req: RSM-07 RSM-10 RSM-04
TEST(UCA_RSM_06_SimultaneousEvents, EstopWithServoReadyLostKeepsTheLockout) {
  Rig r;
  r.to_operational(SelectorReading::Auto);
  r.in.estop_closed = {false, false};
  r.plant.servo_ready = false;
  r.cycle();
  expect_unpowered(r.out);
  EXPECT_EQ(r.st().fault_code, FaultCode::ServoReadyLost);
}

}  // namespace
