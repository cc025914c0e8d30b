// SPDX-License-Identifier: Apache-2.0
// The behaviour changes of the requirement review (issue 17), one test per row ID of the
// design page: C24 fieldbus/cycle watchdog, C25 standstill monitoring, K36 Reset only after
// the release, K37 test of both E-stop channels, K38 no Servo-on in the stop cycle, C12-C14
// stop watchdog from the first trigger, and the tool offset of the T1 speed (RSM-10).
#include <gtest/gtest.h>

#include "safestate/speed_monitor.hpp"
#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT: test code

// ---------------------------------------------------------------- C24, seed: fieldbus loss

TEST(RSM03_FieldbusWatchdog, LossWhilePoweredIsCat0AndLocksOutForGood) {
  Rig r;
  r.to_auto_running();
  r.plant.fieldbus_ok = false;
  r.cycle();
  EXPECT_EQ(r.cycle_row(), "C24");
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::FieldbusLoss);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_FALSE(r.out.contactor_closed || r.out.drive_enable || r.out.brake_release);
  r.plant.fieldbus_ok = true;  // the bus comes back: the lockout stays
  EXPECT_EQ(r.command(Command::reset()), CommandResult::rejected(RejectReason::LockedOut));
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
}

TEST(RSM03_FieldbusWatchdog, ZeroInitialisedInputsReadAsALoss) {
  // A zero image (WKC 0) is a loss from the first cycle: the manager's own watchdog says so.
  SystemStateManager m(flange_config());
  ScanInputs zero_bus = healthy();
  zero_bus.bus = DriveBusImage{};
  (void)m.cycle(zero_bus);
  EXPECT_EQ(m.status().fault_code, FaultCode::FieldbusLoss);
  Rig r;
  r.boot();
  r.plant.fieldbus_ok = false;
  r.cycle();
  EXPECT_EQ(r.st().fault_code, FaultCode::FieldbusLoss);
}

// ---------------------------------------------------------------- C25: standstill monitoring

TEST(RSM11_StandstillMonitoring, MotionInHoldIsCat0AndLockout) {
  Rig r;
  r.to_hold();
  ASSERT_TRUE(r.out.contactor_closed);
  r.in.qd = kSlow;  // the arm creeps although nothing is commanded
  r.cycle();
  EXPECT_EQ(r.cycle_row(), "C25");
  EXPECT_EQ(r.st().fault_code, FaultCode::StandstillViolation);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_FALSE(r.out.contactor_closed || r.out.drive_enable || r.out.brake_release);
}

TEST(RSM11_StandstillMonitoring, MotionInAutoIdleAndManualIdleIsCat0AndLockout) {
  for (const SelectorReading mode : {SelectorReading::Auto, SelectorReading::T1}) {
    Rig r;
    r.to_operational(mode);
    r.in.qd = kSlow;
    r.cycle();
    EXPECT_EQ(r.st().fault_code, FaultCode::StandstillViolation) << to_string(mode);
  }
}

TEST(RSM11_StandstillMonitoring, AJogStopIsMonitoredUntilStandstillAndAfterIt) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  ASSERT_EQ(r.command(Command::jog_stop()), CommandResult::accepted());
  ASSERT_EQ(r.state(), StateId::Stopping);  // ramp-down requested, stop timer running
  r.cycle();                                // still decelerating
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_TRUE(r.out.ramp_down_request);
  r.in.qd = kRest;
  r.cycle();  // at rest: StandStill, monitoring from now on
  r.in.qd = kSlow;
  r.cycle();
  EXPECT_EQ(r.st().fault_code, FaultCode::StandstillViolation);
}

// ---------------------------------------------------------------- K36: Reset after the release

TEST(RSM05_Estop, ResetSubmittedWhilePressedIsRejectedEvenIfPoppedInTheReleaseCycle) {
  Rig r;
  r.boot();
  r.in.estop_closed = {false, false};
  r.cycle();
  ASSERT_EQ(r.submit(Command::reset()), SubmitResult::queued);  // issued while pressed
  r.in.estop_closed = {true, true};
  r.cycle();  // release (C07) and pop in the same cycle
  EXPECT_EQ(r.cycle_row(), "C07");
  EXPECT_EQ(r.command_row(), "K36");
  EXPECT_EQ(r.st().command_result, CommandResult::rejected(RejectReason::EstopPressed));
  EXPECT_EQ(r.state(), StateId::EstopResetNeeded);
  EXPECT_EQ(r.command(Command::reset()), CommandResult::accepted());  // issued after it
  EXPECT_EQ(r.state(), StateId::Idle);
}

TEST(RSM05_Estop, EveryCommandQueuedBeforeTheReleaseIsStale) {
  Rig r;
  r.boot();
  r.in.estop_closed = {false, false};
  r.cycle();
  for (int i = 0; i < 3; ++i) ASSERT_EQ(r.submit(Command::reset()), SubmitResult::queued);
  r.in.estop_closed = {true, true};
  r.cycle();
  EXPECT_EQ(r.st().stale_commands, 2U);  // three queued, one popped
  r.cycles(2);
  EXPECT_EQ(r.st().command_result, CommandResult::rejected(RejectReason::EstopPressed));
  EXPECT_EQ(r.st().stale_commands, 0U);
  EXPECT_EQ(r.state(), StateId::EstopResetNeeded);
}

// ---------------------------------------------------------------- K37: test of both channels

TEST(RSM04_ChannelTest, ResetAfterAOneChannelDemandNeedsBothChannelsSeenOpen) {
  Rig r;
  r.boot();
  r.in.estop_closed = {true, false};  // only B opens (A may be welded), shorter than D
  r.cycle();
  r.in.estop_closed = {true, true};
  r.cycle();
  ASSERT_EQ(r.state(), StateId::EstopResetNeeded);
  EXPECT_EQ(r.command(Command::reset()), CommandResult::rejected(RejectReason::ChannelTestPending));
  EXPECT_EQ(r.command_row(), "K37");
  r.in.estop_closed = {false, false};  // the operator presses once more: both open
  r.cycle();
  r.in.estop_closed = {true, true};
  r.cycle();
  EXPECT_EQ(r.command(Command::reset()), CommandResult::accepted());
  EXPECT_FALSE(r.st().estop_tested_a || r.st().estop_tested_b);  // a new test starts
}

// ---------------------------------------------------------------- K38: no Servo-on in the stop cycle

TEST(RSM06_ServoOn, ServoOnPoppedInTheCycleThatRemovedPowerIsRejected) {
  Rig r;
  r.to_operational(SelectorReading::Auto);
  ASSERT_EQ(r.command(Command::servo_off()), CommandResult::accepted());
  ASSERT_EQ(r.state(), StateId::Stopping);
  ASSERT_EQ(r.submit(Command::servo_on()), SubmitResult::queued);
  r.cycle();  // at rest: C18 -> IDLE, then the Servo-on
  EXPECT_EQ(r.cycle_row(), "C18");
  EXPECT_EQ(r.command_row(), "K38");
  EXPECT_EQ(r.state(), StateId::Idle);
  EXPECT_FALSE(r.out.contactor_closed);  // power was off for this cycle
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
}

// ---------------------------------------------------------------- C12-C14: stop watchdog

TEST(RSM11_Stopping, EscalatedStopIsCutWithinMaxStopCyclesOfTheFirstTrigger) {
  Config c = flange_config();
  c.max_stop_cycles = 20;
  Rig r(c);
  r.to_auto_running();
  (void)r.command(Command::pause());  // first trigger: Cat 2
  std::uint32_t ramping = 1;
  r.cycles(10);
  ramping += 10;
  r.in.safeguard_closed.a = false;  // escalation to Cat 1, the arm still moving
  while (r.out.ramp_down_request) {
    r.cycle();
    if (r.out.ramp_down_request) ++ramping;
  }
  EXPECT_EQ(r.st().fault_code, FaultCode::StopTimeout);
  EXPECT_EQ(ramping, c.max_stop_cycles + 1);  // the trigger cycle + max_stop_cycles
}

// ---------------------------------------------------------------- RSM-10: tool offset

TEST(RSM10_TcpSpeed, ALongToolIsMeasuredAtItsTip) {
  Config flange = flange_config();
  Config tool = flange_config();
  tool.tool_offset_m = {0.0, 0.0, 0.5};  // a 500 mm tool along the flange z axis
  const SpeedMonitor at_flange(flange);
  const SpeedMonitor at_tip(tool);
  // Wrist joint 5 turning: the flange barely moves, the tool tip sweeps.
  const JointVector qd{0.0, 0.0, 0.0, 0.0, 0.6, 0.0};
  const double v_flange = at_flange.tcp_speed_mm_s(kPose, qd);
  const double v_tip = at_tip.tcp_speed_mm_s(kPose, qd);
  EXPECT_LT(v_flange, 250.0);
  EXPECT_GT(v_tip, 250.0);
  EXPECT_EQ(at_flange.classify(kPose, qd), SpeedLevel::Moving);
  EXPECT_EQ(at_tip.classify(kPose, qd), SpeedLevel::OverT1);
  // The tip is 0.5 m from the flange along its z axis.
  const auto p_flange = at_flange.kinematics().forward(kPose);
  const auto p_tip = at_tip.kinematics().forward(kPose);
  EXPECT_NEAR((p_tip.translation() - p_flange.translation()).norm(), 0.5, 1e-12);
}

TEST(RSM10_TcpSpeed, T1OverspeedAtTheToolTipLocksOut) {
  Config c = flange_config();
  c.tool_offset_m = {0.0, 0.0, 0.5};
  Rig r(c);
  r.to_jogging(SelectorReading::T1);
  r.in.qd = JointVector{0.0, 0.0, 0.0, 0.0, 0.6, 0.0};
  r.cycle();
  EXPECT_EQ(r.st().fault_code, FaultCode::T1Overspeed);
}

}  // namespace
