// SPDX-License-Identifier: Apache-2.0
// SystemStateManager: Servo-on (RSM-06), arming (RSM-07), AUTO (RSM-08), manual (RSM-09),
// T1 speed (RSM-10), stopping and pause (RSM-11), commands (RSM-13), queue (RSM-14),
// outputs (RSM-16) and the PLCopen axes it drives (RSM-17).
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <iterator>
#include <thread>
#include <vector>

#include "safestate/jog_setpoint.hpp"
#include "safestate/scan_outputs.hpp"
#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT

// ---------------------------------------------------------------- RSM-06 Servo-on

TEST(RSM06_ServoOn, AcceptedInIdleInAutoWithTheGateClosed) {
  Rig r;
  r.boot();
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
  EXPECT_EQ(r.command_row(), "K12");
  EXPECT_EQ(r.state(), StateId::Arming);
  EXPECT_EQ(r.st().session_mode, OperatingMode::Auto);
  EXPECT_TRUE(r.out.contactor_closed);
}

TEST(RSM06_ServoOn, RejectedOutsideIdle) {
  Rig r;
  r.to_operational();
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::WrongState));
  Rig r2;
  r2.to_reset_needed();
  EXPECT_EQ(r2.command(Command::servo_on()), CommandResult::rejected(RejectReason::WrongState));
}

TEST(RSM06_ServoOn, RejectedWithADriveFault) {
  Rig r;
  r.boot();
  r.plant.drive_fault = true;
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::DriveFault));
  EXPECT_EQ(r.state(), StateId::Idle);
}

TEST(RSM06_ServoOn, RejectedWithAnInvalidSelector) {
  Rig r;
  r.boot();
  r.in.selector = {true, true, false};
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::SelectorInvalid));
}

TEST(RSM06_ServoOn, RejectedInAutoWithTheSafeguardOpen) {
  Rig r;
  r.boot();
  r.in.safeguard_closed = {false, false};
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::SafeguardOpen));
}

TEST(RSM06_ServoOn, RejectedInManualUnlessTheEnablingDeviceIsInMiddle) {
  for (const SelectorReading mode : {SelectorReading::T1, SelectorReading::T2}) {
    for (const EnablePosition p : {EnablePosition::Released, EnablePosition::Panic}) {
      Rig r;
      r.boot(mode);
      if (mode == SelectorReading::T2) (void)r.command(Command::t2_confirm());
      r.in.enabling = {p, p};
      EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::EnableNotMiddle));
    }
  }
}

TEST(RSM06_ServoOn, ManualModesDoNotNeedTheSafeguard) {
  Rig r;
  r.boot(SelectorReading::T1);
  r.in.safeguard_closed = {false, false};
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
}

TEST(RSM06_ServoOn, T2NeedsAnExplicitConfirmation) {
  Rig r;
  r.boot(SelectorReading::T2);
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::T2NotConfirmed));
  EXPECT_EQ(r.command(Command::t2_confirm()), CommandResult::accepted());
  EXPECT_TRUE(r.st().t2_confirmed);
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
  EXPECT_EQ(r.st().session_mode, OperatingMode::T2);
  EXPECT_FALSE(r.st().t2_confirmed);  // only meaningful in IDLE
}

TEST(RSM06_ServoOn, T2ConfirmationIsForgottenWhenTheSelectorLeavesT2) {
  Rig r;
  r.boot(SelectorReading::T2);
  (void)r.command(Command::t2_confirm());
  r.in = healthy(SelectorReading::T1);
  r.cycle();
  EXPECT_EQ(r.cycle_row(), "C22");
  EXPECT_FALSE(r.st().t2_confirmed);
  r.in = healthy(SelectorReading::T2);
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::rejected(RejectReason::T2NotConfirmed));
}

TEST(RSM06_ServoOn, T2ConfirmIsOnlyAcceptedInIdleWithT2Selected) {
  Rig r;
  r.boot(SelectorReading::T1);
  EXPECT_EQ(r.command(Command::t2_confirm()), CommandResult::rejected(RejectReason::WrongMode));
  Rig r2;
  r2.to_operational(SelectorReading::T1);
  EXPECT_EQ(r2.command(Command::t2_confirm()), CommandResult::rejected(RejectReason::WrongState));
}

TEST(RSM06_ServoOn, T2ConfirmationIsClearedByLeavingIdle) {
  Rig r;
  r.boot(SelectorReading::T2);
  (void)r.command(Command::t2_confirm());
  r.in.estop_closed = {false, false};
  r.cycle();
  r.in.estop_closed = {true, true};
  r.cycle();
  (void)r.command(Command::reset());
  ASSERT_EQ(r.state(), StateId::Idle);
  EXPECT_FALSE(r.st().t2_confirmed);
}

// ---------------------------------------------------------------- RSM-07 arming

TEST(RSM07_Arming, ArmingPowersTheDrivesAndReadyEntersTheSubStateOfTheMode) {
  for (const SelectorReading mode : {SelectorReading::Auto, SelectorReading::T1, SelectorReading::T2}) {
    Rig r;
    r.to_operational(mode);
    EXPECT_EQ(r.state(), mode == SelectorReading::Auto ? StateId::AutoIdle : StateId::ManualIdle);
    EXPECT_TRUE(r.out.contactor_closed);
    EXPECT_TRUE(r.out.drive_enable);
    EXPECT_TRUE(r.out.brake_release);
  }
}

TEST(RSM07_Arming, DriveFaultDuringArmingLocksOut) {
  Rig r;
  r.boot();
  r.plant.servo_ready = false;
  (void)r.command(Command::servo_on());
  r.cycles(3);
  r.plant.drive_fault = true;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::DriveFault);
  EXPECT_FALSE(r.out.contactor_closed);
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::ErrorStop);
}

TEST(RSM07_Arming, ArmingTimesOutAfterExactlyTheConfiguredCycles) {
  Config c = flange_config();
  c.arming_timeout_cycles = 10;
  Rig r(c);
  r.boot();
  r.plant.servo_ready = false;
  (void)r.command(Command::servo_on());
  EXPECT_EQ(r.st().state_cycles, 0U);
  r.cycles(10);  // 10 full cycles after the Servo-on cycle
  EXPECT_EQ(r.state(), StateId::Arming);
  EXPECT_EQ(r.st().state_cycles, 10U);
  r.cycle();
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::ArmingTimeout);
  EXPECT_EQ(r.cycle_row(), "C16");
}

TEST(RSM07_Arming, ReadyInTheLastAllowedCycleIsInTime) {
  Config c = flange_config();
  c.arming_timeout_cycles = 10;
  Rig r(c);
  r.boot();
  r.plant.servo_ready = false;
  (void)r.command(Command::servo_on());
  r.cycles(10);
  r.plant.servo_ready = true;
  r.cycle();  // C15 precedes C16
  EXPECT_EQ(r.state(), StateId::AutoIdle);
}

// ---------------------------------------------------------------- RSM-08 AUTO

TEST(RSM08_Auto, StartIsAcceptedOnlyInAutoIdleWithTheGateClosed) {
  Rig r;
  r.boot();
  EXPECT_EQ(r.command(Command::start()), CommandResult::rejected(RejectReason::WrongState));
  Rig r2;
  r2.to_operational();
  EXPECT_EQ(r2.command(Command::start()), CommandResult::accepted());
  EXPECT_EQ(r2.state(), StateId::AutoRunning);
  for (const AxisState a : r2.out.axes) EXPECT_EQ(a, AxisState::SynchronizedMotion);
  EXPECT_EQ(r2.command(Command::start()), CommandResult::rejected(RejectReason::WrongState));
}

TEST(RSM08_Auto, StartInAManualModeIsWrongMode) {
  Rig r;
  r.to_operational(SelectorReading::T1);
  EXPECT_EQ(r.command(Command::start()), CommandResult::rejected(RejectReason::WrongMode));
  Rig r2;
  r2.to_jogging(SelectorReading::T2);
  EXPECT_EQ(r2.command(Command::start()), CommandResult::rejected(RejectReason::WrongMode));
}

TEST(RSM08_Auto, SafeguardOpenedInAutoStopsCat1EvenWhenIdle) {
  Rig r;
  r.to_operational();
  r.in.safeguard_closed.b = false;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.cycle_row(), "C13");
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);
}

TEST(RSM08_Auto, StartWithTheGateOpeningInTheSameCycleIsRefused) {
  Rig r;
  r.to_operational();
  ASSERT_EQ(r.submit(Command::start()), SubmitResult::queued);
  r.in.safeguard_closed.a = false;
  r.cycle();  // C13 first, then K16 (state is STOPPING)
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.st().command_result, CommandResult::rejected(RejectReason::WrongState));
}

TEST(RSM08_Auto, JogCommandsInAutoAreRejectedAndChangeNothing) {
  Rig r;
  r.to_auto_running();
  const StatusRecord before = r.st();
  EXPECT_EQ(r.command(Command::jog_start(1, 1, 100)), CommandResult::rejected(RejectReason::JogInAuto));
  EXPECT_EQ(without_command_fields(r.st()), without_command_fields(before));
  EXPECT_EQ(r.command(Command::jog_stop()), CommandResult::rejected(RejectReason::JogInAuto));
  EXPECT_EQ(without_command_fields(r.st()), without_command_fields(before));
  Rig idle;
  idle.boot(SelectorReading::Auto);  // selector AUTO is enough
  EXPECT_EQ(idle.command(Command::jog_start(1, 1, 100)), CommandResult::rejected(RejectReason::JogInAuto));
}

// ---------------------------------------------------------------- RSM-09 manual

TEST(RSM09_Manual, JogStartIsAcceptedOnlyInManualIdleWithTheEnablingDeviceInMiddle) {
  Rig r;
  r.boot(SelectorReading::T1);
  EXPECT_EQ(r.command(Command::jog_start(1, 1, 100)), CommandResult::rejected(RejectReason::WrongState));
  Rig r2;
  r2.to_operational(SelectorReading::T1);
  EXPECT_EQ(r2.command(Command::jog_start(3, -1, 100)), CommandResult::accepted());
  EXPECT_EQ(r2.state(), StateId::ManualJogging);
  EXPECT_EQ(r2.st().jog_axis, 3);
  EXPECT_EQ(r2.st().jog_direction, -1);
  EXPECT_EQ(r2.out.commanded_speed_mm_s, 100);
  EXPECT_EQ(r2.command(Command::jog_start(3, -1, 100)), CommandResult::rejected(RejectReason::WrongState));
}

TEST(RSM09_Manual, JogArgumentsAreValidated) {
  Rig r;
  r.to_operational(SelectorReading::T1);
  for (const Command c : {Command::jog_start(0, 1, 10), Command::jog_start(7, 1, 10), Command::jog_start(1, 0, 10),
                          Command::jog_start(1, 2, 10), Command::jog_start(1, 1, 0), Command::jog_start(1, -1, -5)}) {
    EXPECT_EQ(r.command(c), CommandResult::rejected(RejectReason::InvalidArgument));
    EXPECT_EQ(r.state(), StateId::ManualIdle);
  }
}

// A JOG_START built field by field with its direction left unset carries direction 0,
// which is no direction: rejected at K26 like any other invalid argument, never a jog.
TEST(RSM09_Manual, AJogStartWithItsDirectionLeftUnsetIsRejected) {
  Rig r;
  r.to_operational(SelectorReading::T1);
  Command c{};
  c.kind = CommandKind::JogStart;
  c.axis = 1;
  c.speed_mm_s = 100;
  EXPECT_EQ(r.command(c), CommandResult::rejected(RejectReason::InvalidArgument));
  EXPECT_EQ(r.state(), StateId::ManualIdle);
}

// A command is a value the operator interface submits and reads back (the queue copies it,
// the binding and the conformance traces show its fields): the factories of commands
// without arguments carry their kind and zero jog arguments, as a command built field by
// field does; only jog_start sets them.
TEST(RSM13_Commands, CommandsWithoutArgumentsCarryZeroJogArguments) {
  const Command made[] = {Command::reset(), Command::servo_on(), Command::servo_off(), Command::start(),
                          Command::pause(), Command::resume(),   Command::jog_stop(),  Command::t2_confirm()};
  const CommandKind kinds[] = {CommandKind::Reset, CommandKind::ServoOn, CommandKind::ServoOff, CommandKind::Start,
                               CommandKind::Pause, CommandKind::Resume,  CommandKind::JogStop,  CommandKind::T2Confirm};
  for (std::size_t i = 0; i < std::size(made); ++i) {
    EXPECT_EQ(made[i].kind, kinds[i]) << i;
    EXPECT_EQ(made[i].axis, 0) << to_string(kinds[i]);
    EXPECT_EQ(made[i].direction, 0) << to_string(kinds[i]);
    EXPECT_EQ(made[i].speed_mm_s, 0) << to_string(kinds[i]);
  }
  const Command jog = Command::jog_start(3, -1, 120);
  EXPECT_EQ((std::array<std::int32_t, 3>{jog.axis, jog.direction, jog.speed_mm_s}),
            (std::array<std::int32_t, 3>{3, -1, 120}));
  EXPECT_EQ(jog.kind, CommandKind::JogStart);
}

// The outputs of a scan are a value: != is exactly the negation of ==.
TEST(RSM16_ScanOutputs, OutputsDifferExactlyWhenTheyAreNotEqual) {
  const ScanOutputs a{};
  ScanOutputs b{};
  EXPECT_FALSE(a != b);
  b.ramp_down_request = true;
  EXPECT_TRUE(a != b);
  EXPECT_FALSE(a == b);
}

// The jog setpoint (axis, direction, speed) is a value: two setpoints are equal exactly
// when all three fields are, and != is its negation.
TEST(RSM09_Manual, JogSetpointsAreEqualExactlyWhenAxisDirectionAndSpeedAre) {
  const JogSetpoint a{2, -1, 100};
  EXPECT_TRUE(a == (JogSetpoint{2, -1, 100}));
  EXPECT_FALSE(a != (JogSetpoint{2, -1, 100}));
  for (const JogSetpoint& b : {JogSetpoint{3, -1, 100}, JogSetpoint{2, 1, 100}, JogSetpoint{2, -1, 101}}) {
    EXPECT_FALSE(a == b);
    EXPECT_TRUE(a != b);
  }
}

TEST(RSM09_Manual, ReleasingTheEnablingDeviceStopsCat1) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  r.in.enabling = {EnablePosition::Released, EnablePosition::Released};
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.cycle_row(), "C14");
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);
  EXPECT_EQ(r.st().jog_axis, 0);  // a Cat 1 stop keeps no jog
  r.in.qd = kRest;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle);
}

TEST(RSM09_Manual, PanicCutsPowerAtOnceAndReturnsToIdle) {
  Rig r;
  r.to_jogging(SelectorReading::T2);
  r.in.enabling = {EnablePosition::Panic, EnablePosition::Panic};
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle);
  EXPECT_EQ(r.cycle_row(), "C11");
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_FALSE(r.out.contactor_closed);
}

TEST(RSM09_Manual, PanicOnOneChannelIsEnough) {
  Rig r;
  r.to_operational(SelectorReading::T1);
  r.in.enabling.b = EnablePosition::Panic;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
}

TEST(RSM09_Manual, TheSafeguardIsNotRequiredInManualModes) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  r.in.safeguard_closed = {false, false};
  r.cycles(10);
  EXPECT_EQ(r.state(), StateId::ManualJogging);
}

TEST(RSM09_Manual, JogStopRampsDownThenReturnsToManualIdleAtStandstill) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  EXPECT_EQ(r.command(Command::jog_stop()), CommandResult::accepted());
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat2);
  EXPECT_TRUE(r.out.ramp_down_request);
  EXPECT_EQ(r.out.commanded_speed_mm_s, 0);
  EXPECT_EQ(r.command(Command::jog_stop()), CommandResult::rejected(RejectReason::WrongState));
  r.in.qd = kRest;
  r.cycle();
  EXPECT_EQ(r.cycle_row(), "C28");
  EXPECT_EQ(r.state(), StateId::ManualIdle);
  EXPECT_FALSE(r.out.ramp_down_request);
}

// ---------------------------------------------------------------- RSM-10 T1 speed (integration)

TEST(RSM10_T1Speed, SpeedLevelsComeFromTheArmKinematics) {
  const SpeedMonitor mon{Config{}};
  EXPECT_EQ(mon.classify(kPose, kRest), SpeedLevel::Zero);
  EXPECT_EQ(mon.classify(kPose, kSlow), SpeedLevel::Moving);
  EXPECT_EQ(mon.classify(kPose, kMedium), SpeedLevel::OverT1);
  EXPECT_EQ(mon.classify(kPose, kFast), SpeedLevel::OverT2);
  EXPECT_GT(mon.tcp_speed_mm_s(kPose, kMedium), 250.0);
  EXPECT_LT(mon.tcp_speed_mm_s(kPose, kMedium), 1000.0);
  EXPECT_GT(mon.tcp_speed_mm_s(kPose, kFast), 1000.0);
  EXPECT_LT(mon.tcp_speed_mm_s(kPose, kSlow), 250.0);
  // At or below the zero threshold on every joint is standstill.
  EXPECT_EQ(mon.classify(kPose, JointVector{0.001, -0.001, 0.0, 0.0005, 0.0, 0.0}), SpeedLevel::Zero);
  // A wrist-only rotation is MOVING although the flange origin barely moves.
  EXPECT_EQ(mon.classify(kPose, JointVector{0, 0, 0, 0, 0, 0.5}), SpeedLevel::Moving);
}

TEST(RSM10_T1Speed, UnreadableJointVelocityIsTreatedAsOverspeed) {
  const SpeedMonitor mon{Config{}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(mon.classify(kPose, JointVector{nan, 0, 0, 0, 0, 0}), SpeedLevel::OverT2);
}

// A joint turning backwards moves as much as one turning forwards (the zero-speed test
// compares the magnitude; without it every negative velocity reads as standstill).
TEST(RSM10_T1Speed, AJointTurningBackwardsIsNotAtRest) {
  const SpeedMonitor mon{Config{}};
  EXPECT_EQ(mon.classify(kPose, JointVector{-kSlow[0], 0, 0, 0, 0, 0}), SpeedLevel::Moving);
  EXPECT_EQ(mon.classify(kPose, JointVector{0, 0, 0, 0, 0, -0.5}), SpeedLevel::Moving);
  EXPECT_EQ(mon.classify(kPose, JointVector{-kMedium[0], 0, 0, 0, 0, 0}), SpeedLevel::OverT1);
}

// RSM-10: the T1 limit is a maximum, 250 mm/s itself is allowed; only above it is an
// overspeed. The joint-1 rate whose TCP speed is the limit exactly is found by nudging
// the last bits of limit / (speed per rad/s).
TEST(RSM10_T1Speed, ExactlyTheT1LimitIsNotAnOverspeed) {
  const Config config = flange_config();
  const SpeedMonitor mon{config};
  const double limit = static_cast<double>(config.t1_speed_limit_mm_s);
  double w = limit / mon.tcp_speed_mm_s(kPose, JointVector{1.0, 0, 0, 0, 0, 0});
  for (int i = 0; i < 64; ++i) {
    const double got = mon.tcp_speed_mm_s(kPose, JointVector{w, 0, 0, 0, 0, 0});
    if (got == limit) {
      break;
    }
    w = std::nextafter(w, got < limit ? limit : 0.0);
  }
  ASSERT_EQ(mon.tcp_speed_mm_s(kPose, JointVector{w, 0, 0, 0, 0, 0}), limit);
  EXPECT_EQ(mon.classify(kPose, JointVector{w, 0, 0, 0, 0, 0}), SpeedLevel::Moving);
  EXPECT_EQ(mon.classify(kPose, JointVector{w * (1 + 1e-9), 0, 0, 0, 0, 0}), SpeedLevel::OverT1);
}

TEST(RSM10_T1Speed, CommandedJogSpeedIsClampedTo250InT1) {
  Rig r;
  r.to_operational(SelectorReading::T1);
  EXPECT_EQ(r.command(Command::jog_start(1, 1, 1000)), CommandResult::accepted());
  EXPECT_EQ(r.st().jog_speed_mm_s, 250);
  EXPECT_EQ(r.out.commanded_speed_mm_s, 250);
}

TEST(RSM10_T1Speed, JogSpeedIsNotClampedInT2) {
  Rig r;
  r.to_operational(SelectorReading::T2);
  EXPECT_EQ(r.command(Command::jog_start(1, 1, 1000)), CommandResult::accepted());
  EXPECT_EQ(r.out.commanded_speed_mm_s, 1000);
}

TEST(RSM10_T1Speed, MeasuredOverspeedInT1CutsPowerInTheSameCycle) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  r.in.qd = kFast;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::T1Overspeed);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_FALSE(r.out.contactor_closed);
  EXPECT_FALSE(r.out.drive_enable);
}

TEST(RSM10_T1Speed, OverspeedWhileStoppingInT1AlsoCutsPower) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  (void)r.command(Command::pause());
  ASSERT_EQ(r.state(), StateId::Stopping);
  r.in.qd = kFast;
  r.cycle();
  EXPECT_EQ(r.st().fault_code, FaultCode::T1Overspeed);
}

TEST(RSM10_T1Speed, HighSpeedInT2OrAutoIsNotAT1Overspeed) {
  Rig r;
  r.to_jogging(SelectorReading::T2, 1000);
  r.in.qd = kMedium;  // above T1's limit, below T2's (above it is C29's)
  r.cycles(5);
  EXPECT_EQ(r.state(), StateId::ManualJogging);
  Rig a;
  a.to_auto_running();
  a.in.qd = kFast;
  a.cycles(5);
  EXPECT_EQ(a.state(), StateId::AutoRunning);
}

TEST(RSM10_T1Speed, AConfiguredLimitIsUsedForClampAndOverspeed) {
  Config c = flange_config();
  c.t1_speed_limit_mm_s = 20;
  Rig r(c);
  r.to_operational(SelectorReading::T1);
  (void)r.command(Command::jog_start(1, 1, 100));
  EXPECT_EQ(r.out.commanded_speed_mm_s, 20);
  r.in.qd = kSlow;  // ~40 mm/s at this pose: over 20
  ASSERT_GT(r.m.speed_monitor().tcp_speed_mm_s(kPose, kSlow), 20.0);
  r.cycle();
  EXPECT_EQ(r.st().fault_code, FaultCode::T1Overspeed);
}

// ---------------------------------------------------------------- RSM-11 stopping, pause

TEST(RSM11_Stopping, Cat1StopTimesOutAfterExactlyMaxStopCyclesAndCutsPower) {
  Config c = flange_config();
  c.max_stop_cycles = 20;
  Rig r(c);
  r.to_auto_running();
  (void)r.command(Command::servo_off());
  ASSERT_EQ(r.state(), StateId::Stopping);
  r.cycles(20);  // robot never stops
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.st().state_cycles, 20U);
  r.cycle();
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::StopTimeout);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_FALSE(r.out.contactor_closed);
}

TEST(RSM11_Stopping, PauseHoldsAndResumeReturnsToAutoRunning) {
  Rig r;
  r.to_hold();
  EXPECT_EQ(r.st().resume_to, ResumeTarget::AutoRunning);
  EXPECT_EQ(r.command(Command::resume()), CommandResult::accepted());
  EXPECT_EQ(r.state(), StateId::AutoRunning);
  EXPECT_EQ(r.st().resume_to, ResumeTarget::None);
}

TEST(RSM11_Stopping, PausedJogResumesWithItsSetpoint) {
  Rig r;
  r.to_jogging(SelectorReading::T1, 1000);
  EXPECT_EQ(r.command(Command::pause()), CommandResult::accepted());
  EXPECT_EQ(r.st().resume_to, ResumeTarget::ManualJogging);
  EXPECT_EQ(r.st().jog_speed_mm_s, 250);
  EXPECT_EQ(r.out.commanded_speed_mm_s, 0);  // not jogging while stopping
  r.in.qd = kRest;
  r.cycle();
  ASSERT_EQ(r.state(), StateId::Hold);
  EXPECT_EQ(r.st().jog_axis, 2);
  EXPECT_EQ(r.command(Command::resume()), CommandResult::accepted());
  EXPECT_EQ(r.state(), StateId::ManualJogging);
  EXPECT_EQ(r.out.commanded_speed_mm_s, 250);
  EXPECT_EQ(r.st().jog_axis, 2);
  EXPECT_EQ(r.st().jog_direction, 1);
}

TEST(RSM11_Stopping, PauseAndResumeOutsideTheirStatesAreWrongState) {
  Rig r;
  r.to_operational();
  EXPECT_EQ(r.command(Command::pause()), CommandResult::rejected(RejectReason::WrongState));
  EXPECT_EQ(r.command(Command::resume()), CommandResult::rejected(RejectReason::WrongState));
  Rig s;
  s.to_auto_running();
  (void)s.command(Command::pause());
  ASSERT_EQ(s.state(), StateId::Stopping);
  EXPECT_EQ(s.command(Command::resume()), CommandResult::rejected(RejectReason::WrongState));
  EXPECT_EQ(s.command(Command::servo_off()), CommandResult::rejected(RejectReason::WrongState));
}

TEST(RSM11_Stopping, GateOpenedInHoldEscalatesToCat1SoResumeIsRefused) {
  Rig r;
  r.to_hold();
  r.in.safeguard_closed.a = false;
  ASSERT_EQ(r.submit(Command::resume()), SubmitResult::queued);
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);
  EXPECT_EQ(r.st().resume_to, ResumeTarget::None);
  EXPECT_EQ(r.st().command_result, CommandResult::rejected(RejectReason::WrongState));
}

// The stop watchdog runs from the first trigger of the episode (C12-C14 keep state_cycles).
TEST(RSM11_Stopping, Cat2StopEscalatesToCat1AndKeepsTheStopTimer) {
  Rig r;
  r.to_auto_running();
  (void)r.command(Command::pause());
  r.cycles(5);
  ASSERT_EQ(r.st().state_cycles, 5U);
  r.in.safeguard_closed.a = false;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);
  EXPECT_EQ(r.st().state_cycles, 6U);  // kept, and this cycle counted
  r.in.qd = kRest;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle);  // Cat 1 ends unpowered, not in HOLD
}

TEST(RSM11_Stopping, ServoOffFromHoldIsACat1Stop) {
  Rig r;
  r.to_hold();
  EXPECT_EQ(r.command(Command::servo_off()), CommandResult::accepted());
  EXPECT_EQ(r.state(), StateId::Stopping);
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle);
}

// ---------------------------------------------------------------- RSM-13 commands

TEST(RSM13_Commands, ACycleWithAnEmptyQueueReportsNoCommand) {
  Rig r;
  r.boot();
  (void)r.command(Command::reset());
  EXPECT_EQ(r.st().command_result, CommandResult::rejected(RejectReason::WrongState));
  r.cycle();
  EXPECT_EQ(r.st().command_result, CommandResult::none());
  EXPECT_EQ(r.st().last_reject_reason, RejectReason::WrongState);  // kept
  EXPECT_EQ(r.m.last_rows().command, nullptr);
}

TEST(RSM13_Commands, ARejectedCommandChangesNothingButTheCommandFields) {
  // Every command in every state the scripted rigs reach: a reject leaves the whole status
  // (and the outputs) as the same cycle without the command would have left them.
  using SetupFn = void (*)(Rig&);
  const SetupFn setups[] = {
      [](Rig& r) { r.boot(); },
      [](Rig& r) { r.boot(SelectorReading::T2); },
      [](Rig& r) { r.to_reset_needed(); },
      [](Rig& r) { r.to_operational(SelectorReading::Auto); },
      [](Rig& r) { r.to_operational(SelectorReading::T1); },
      [](Rig& r) { r.to_auto_running(); },
      [](Rig& r) { r.to_jogging(SelectorReading::T1); },
      [](Rig& r) { r.to_hold(); },
      [](Rig& r) {
        r.to_auto_running();
        (void)r.command(Command::pause());
      },
      [](Rig& r) {
        r.boot();
        r.plant.servo_ready = false;
        (void)r.command(Command::servo_on());
      },
  };
  const Command commands[] = {
      Command::reset(),    Command::servo_on(),  Command::servo_off(),         Command::start(),
      Command::pause(),    Command::resume(),    Command::jog_start(1, 1, 10), Command::jog_start(9, 1, 10),
      Command::jog_stop(), Command::t2_confirm()};
  int rejects = 0;
  for (const SetupFn setup : setups) {
    for (const Command& c : commands) {
      Rig with;
      Rig without;
      setup(with);
      setup(without);
      ASSERT_EQ(with.st(), without.st());
      ASSERT_EQ(with.submit(c), SubmitResult::queued);
      with.cycle();
      without.cycle();
      const StatusRecord s = with.st();
      if (s.command_result.outcome() != CommandResult::Outcome::Rejected) continue;
      ++rejects;
      EXPECT_EQ(s.last_reject_reason, s.command_result.reason());
      EXPECT_EQ(without_command_fields(s), without_command_fields(without.st()))
          << to_string(c.kind) << " in " << to_string(s.state);
      EXPECT_EQ(with.out, without.out);
    }
  }
  EXPECT_GT(rejects, 50);
}

// ---------------------------------------------------------------- RSM-14 queue

TEST(RSM14_CommandQueue, AFullQueueRejectsAtOnceAndChangesNothingElse) {
  Rig r;  // default limit 8
  r.boot(SelectorReading::T1);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(r.submit(Command::jog_stop()), SubmitResult::queued);
  const StatusRecord before = r.st();
  EXPECT_EQ(before.queue_length, 8U);
  EXPECT_EQ(r.submit(Command::servo_on()), SubmitResult::queue_full);
  const StatusRecord after = r.st();
  EXPECT_EQ(after.last_reject_reason, RejectReason::QueueFull);
  EXPECT_EQ(after.command_result, before.command_result);
  EXPECT_EQ(without_command_fields(after), without_command_fields(before));
  EXPECT_EQ(r.state(), StateId::Idle);
  // The eight queued commands are each handled, one per cycle; nothing was dropped.
  for (int i = 0; i < 8; ++i) {
    r.cycle();
    EXPECT_EQ(r.st().command_result, CommandResult::rejected(RejectReason::WrongState));
    EXPECT_EQ(r.st().queue_length, static_cast<std::size_t>(7 - i));
  }
  r.cycle();
  EXPECT_EQ(r.st().command_result, CommandResult::none());
  EXPECT_EQ(r.state(), StateId::Idle);  // the rejected Servo-on never ran
}

TEST(RSM14_CommandQueue, TheConfiguredLimitBoundsTheQueue) {
  Config c = flange_config();
  c.command_queue_limit = 2;
  Rig r(c);
  EXPECT_EQ(r.submit(Command::reset()), SubmitResult::queued);
  EXPECT_EQ(r.submit(Command::reset()), SubmitResult::queued);
  EXPECT_EQ(r.submit(Command::reset()), SubmitResult::queue_full);
  c.command_queue_limit = kMaxQueueCapacity;
  Rig big(c);
  for (std::size_t i = 0; i < kMaxQueueCapacity; ++i) EXPECT_EQ(big.submit(Command::reset()), SubmitResult::queued);
  EXPECT_EQ(big.submit(Command::reset()), SubmitResult::queue_full);
}

TEST(RSM14_CommandQueue, CommandsAreHandledOnePerCycleInOrder) {
  Rig r;
  r.to_operational(SelectorReading::T1);
  ASSERT_EQ(r.submit(Command::jog_start(1, 1, 10)), SubmitResult::queued);
  ASSERT_EQ(r.submit(Command::jog_stop()), SubmitResult::queued);
  r.cycle();
  EXPECT_EQ(r.state(), StateId::ManualJogging);
  EXPECT_EQ(r.st().queue_length, 1U);
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Stopping);  // the jog stop's Cat 2 ramp (K32)
  EXPECT_EQ(r.st().queue_length, 0U);
}

TEST(RSM14_CommandQueue, AProducerThreadNeverBlocksAndNothingIsLost) {
  Rig r;
  r.boot(SelectorReading::T1);
  constexpr int kCommands = 20000;
  std::atomic<int> queued{0};
  std::atomic<bool> done{false};
  std::thread producer([&] {
    for (int i = 0; i < kCommands; ++i) {
      if (r.m.submit(Command::jog_stop()) == SubmitResult::queued) queued.fetch_add(1);
    }
    done.store(true);
  });
  int handled = 0;
  while (!done.load() || r.m.queue_length() > 0) {
    r.cycle();
    if (r.st().command_result.outcome() != CommandResult::Outcome::None) ++handled;
  }
  producer.join();
  while (r.m.queue_length() > 0) {
    r.cycle();
    if (r.st().command_result.outcome() != CommandResult::Outcome::None) ++handled;
  }
  EXPECT_EQ(handled, queued.load());
  EXPECT_GT(queued.load(), 0);
}

// ---------------------------------------------------------------- RSM-16 outputs

TEST(RSM16_Outputs, PowerOutputsAreOnExactlyInPoweredStates) {
  Rig r;
  r.to_hold();
  EXPECT_TRUE(r.out.contactor_closed && r.out.drive_enable && r.out.brake_release);
  Rig i;
  i.boot();
  EXPECT_FALSE(i.out.contactor_closed || i.out.drive_enable || i.out.brake_release);
  EXPECT_FALSE(i.out.ramp_down_request || i.out.reset_lamp);
}

TEST(RSM16_Outputs, ResetLampAndRampDownFollowTheirStates) {
  Rig r;
  r.to_reset_needed();
  EXPECT_TRUE(r.out.reset_lamp);
  EXPECT_FALSE(r.out.ramp_down_request);
  Rig s;
  s.to_auto_running();
  (void)s.command(Command::servo_off());
  EXPECT_TRUE(s.out.ramp_down_request);
  EXPECT_FALSE(s.out.reset_lamp);
}

TEST(RSM16_Outputs, CycleReturnsWhatOutputsReportsAfterwards) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  EXPECT_EQ(r.out, r.m.outputs());
}

TEST(RSM16_Outputs, StatusRecordNamesStateModeStopReasonAndFault) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  (void)r.command(Command::start());
  StatusRecord s = r.st();
  EXPECT_EQ(to_string(s.state), "MANUAL_JOGGING");
  EXPECT_EQ(to_string(s.session_mode), "T1");
  EXPECT_EQ(to_string(s.selector), "T1");
  EXPECT_EQ(to_string(s.stop_category), "NONE");
  EXPECT_EQ(to_string(s.last_reject_reason), "WRONG_MODE");
  EXPECT_EQ(to_string(s.command_result), "WRONG_MODE");
  r.plant.drive_fault = true;
  r.cycle();
  s = r.st();
  EXPECT_EQ(to_string(s.fault_code), "DRIVE_FAULT");
  EXPECT_EQ(to_string(s.stop_category), "CAT0");
  EXPECT_EQ(to_string(s.session_mode), "NONE");
}

// ---------------------------------------------------------------- RSM-17 axes in the manager

TEST(RSM17_AxesInManager, ServoOnStopAndPowerOffWalkTheAxesThroughThePlcopenStates) {
  Rig r;
  r.boot();
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::Disabled);
  r.plant.servo_ready = false;
  (void)r.command(Command::servo_on());
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::Disabled);  // ARMING
  r.plant.servo_ready = true;
  r.cycle();
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::StandStill);  // MC_Power on
  (void)r.command(Command::start());
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::SynchronizedMotion);
  r.in.qd = kSlow;
  (void)r.command(Command::servo_off());
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::Stopping);
  r.cycle();
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::Stopping);
  r.in.qd = kRest;
  r.cycle();  // IDLE: power removed
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::Disabled);
}

TEST(RSM17_AxesInManager, JoggingMovesOnlyTheJoggedAxis) {
  Rig r;
  r.to_jogging(SelectorReading::T1);  // axis 2
  for (std::size_t i = 0; i < kAxisCount; ++i) {
    EXPECT_EQ(r.out.axes[i], i == 1 ? AxisState::ContinuousMotion : AxisState::StandStill);
  }
}

TEST(RSM17_AxesInManager, PauseTakesAxesThroughStoppingToStandStill) {
  Rig r;
  r.to_auto_running();
  (void)r.command(Command::pause());
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::Stopping);
  r.in.qd = kRest;
  r.cycle();  // HOLD, speed zero
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::StandStill);
}

TEST(RSM17_AxesInManager, DriveFaultPutsEveryAxisInErrorStopForGood) {
  Rig r;
  r.to_auto_running();
  r.plant.drive_fault = true;
  r.cycle();
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::ErrorStop);
  r.plant.drive_fault = false;
  r.cycles(10);
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::ErrorStop);
}

TEST(RSM17_AxesInManager, OtherLockoutsDisableTheAxes) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  r.in.qd = kFast;
  r.cycle();
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::Disabled);
}

}  // namespace
