// SPDX-License-Identifier: Apache-2.0
// SystemStateManager: states (RSM-01), boot (RSM-12), E-stop (RSM-05), dual-channel inputs
// and the mode selector (RSM-04, RSM-02), stop categories (RSM-03).
#include <gtest/gtest.h>

#include <ostream>
#include <set>

#include "safestate/dual_channel_input.hpp"
#include "safestate/mode_selector.hpp"
#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT

// ---------------------------------------------------------------- RSM-01 states

TEST(RSM01_States, BeforeTheFirstCycleTheManagerIsInBootWithEverythingOff) {
  Rig r;
  const StatusRecord s = r.st();
  EXPECT_EQ(s.state, StateId::Boot);
  EXPECT_EQ(s.selector, SelectorReading::Invalid);
  EXPECT_EQ(s.session_mode, OperatingMode::None);
  EXPECT_EQ(s.stop_category, StopCategory::None);
  EXPECT_EQ(s.fault_code, FaultCode::None);
  EXPECT_EQ(s.last_reject_reason, RejectReason::None);
  EXPECT_EQ(s.command_result, CommandResult::none());
  EXPECT_EQ(s.estop_mismatch + s.safeguard_mismatch + s.enabling_mismatch + s.selector_invalid, 0U);
  EXPECT_EQ(s.queue_length, 0U);
  // ... and the whole record is the default one (no jog: axis, direction, speed 0), as the
  // outputs are the default outputs: a default-built record means "nothing yet"
  EXPECT_EQ(s, StatusRecord{});
  EXPECT_EQ(r.m.outputs(), ScanOutputs{});
  for (const AxisState a : r.m.outputs().axes) EXPECT_EQ(a, AxisState::Disabled);
  EXPECT_EQ(r.m.last_rows().cycle, nullptr);
  EXPECT_EQ(r.m.last_rows().command, nullptr);
}

TEST(RSM01_States, EveryLeafStateIsReachedByAScriptedSession) {
  std::set<StateId> seen;
  Rig r;
  const auto note = [&] { seen.insert(r.state()); };
  note();  // BOOT
  r.in = healthy(SelectorReading::Auto);
  r.in.estop_closed = {false, false};
  r.cycle();
  note();  // ESTOP_ACTIVE
  r.in.estop_closed = {true, true};
  r.cycle();
  note();  // ESTOP_RESET_NEEDED
  (void)r.command(Command::reset());
  note();  // IDLE
  r.plant.servo_ready = false;
  (void)r.command(Command::servo_on());
  note();  // ARMING
  r.plant.servo_ready = true;
  r.cycle();
  note();  // AUTO_IDLE
  (void)r.command(Command::start());
  note();  // AUTO_RUNNING
  (void)r.command(Command::pause());
  note();  // STOPPING
  r.cycle();
  note();  // HOLD (at rest)
  r.in = healthy(SelectorReading::T1);
  r.cycle();  // C12: STOPPING CAT1
  r.cycle();
  note();  // IDLE
  r.plant.servo_ready = false;
  (void)r.command(Command::servo_on());
  r.plant.servo_ready = true;
  r.cycle();
  note();  // MANUAL_IDLE
  (void)r.command(Command::jog_start(1, 1, 50));
  note();  // MANUAL_JOGGING
  r.plant.drive_fault = true;
  r.cycle();
  note();  // ERROR_LOCKOUT
  EXPECT_EQ(seen.size(), kStateCount);
}

TEST(RSM01_States, OperationalSubStatesAndPoweredSetAreAsDesigned) {
  EXPECT_TRUE(is_operational(StateId::AutoIdle));
  EXPECT_TRUE(is_operational(StateId::ManualJogging));
  EXPECT_FALSE(is_operational(StateId::Hold));
  for (const StateId s : kAllStates) {
    const bool powered = s == StateId::Arming || is_operational(s) || s == StateId::Stopping || s == StateId::Hold;
    EXPECT_EQ(is_powered(s), powered) << to_string(s);
  }
}

// ---------------------------------------------------------------- RSM-12 boot

TEST(RSM12_Boot, HealthyBootEntersIdleAfterExactlyOneCycle) {
  Rig r;
  r.in = healthy();
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle);
  EXPECT_EQ(r.cycle_row(), "C05");
  EXPECT_FALSE(r.out.contactor_closed);
}

TEST(RSM12_Boot, BootWithEstopPressedEntersEstopActiveCat0) {
  Rig r;
  r.in = healthy();
  r.in.estop_closed = {true, false};
  r.cycle();
  EXPECT_EQ(r.state(), StateId::EstopActive);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_EQ(r.cycle_row(), "C04");
}

TEST(RSM12_Boot, FailedSelfTestLocksOutWithSelfTestFailed) {
  Rig r;
  r.in = healthy();
  r.in.self_test_ok = false;
  r.in.estop_closed = {false, false};  // the self-test failure wins over the E-stop (C02 first)
  r.cycle();
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::SelfTestFailed);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
}

TEST(RSM12_Boot, InvalidConfigFailsTheSelfTest) {
  Config c = flange_config();
  c.command_queue_limit = 0;
  ASSERT_EQ(validate(c), ConfigError::QueueLimitOutOfRange);
  Rig r(c);
  EXPECT_EQ(r.m.config_error(), ConfigError::QueueLimitOutOfRange);
  r.in = healthy();
  r.cycle();
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::SelfTestFailed);
  EXPECT_EQ(r.cycle_row(), "C02");
}

TEST(RSM12_Boot, SelfTestIsReadInBootOnly) {
  Rig r;
  r.boot();
  r.in.self_test_ok = false;
  r.cycles(5);
  EXPECT_EQ(r.state(), StateId::Idle);
}

TEST(RSM12_Boot, ZeroInitialisedInputsAreTheSafeReading) {
  Rig r;
  r.in = ScanInputs{};
  r.cycle();
  // self_test_ok = false is a failed self-test: the safest outcome.
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_FALSE(r.out.contactor_closed);
}

// ---------------------------------------------------------------- RSM-05 E-stop

class RSM05_EstopPriority : public ::testing::TestWithParam<int> {};

TEST_P(RSM05_EstopPriority, EstopPressedInAnyPoweredStateEntersEstopActiveSameCycle) {
  Rig r;
  switch (GetParam()) {
    case 0:
      r.boot();
      r.plant.servo_ready = false;
      (void)r.command(Command::servo_on());
      break;  // ARMING
    case 1: r.to_operational(SelectorReading::Auto); break;
    case 2: r.to_auto_running(); break;
    case 3: r.to_operational(SelectorReading::T1); break;
    case 4: r.to_jogging(SelectorReading::T1); break;
    case 5:
      r.to_auto_running();
      (void)r.command(Command::pause());
      break;  // STOPPING CAT2
    case 6: r.to_hold(); break;
    default: FAIL();
  }
  ASSERT_TRUE(is_powered(r.state())) << to_string(r.state());
  r.in.estop_closed.b = false;  // one channel is enough (1oo2)
  r.cycle();
  EXPECT_EQ(r.state(), StateId::EstopActive);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_FALSE(r.out.contactor_closed);
  EXPECT_FALSE(r.out.drive_enable);
  EXPECT_FALSE(r.out.brake_release);
  EXPECT_EQ(r.cycle_row(), "C06");
}

INSTANTIATE_TEST_SUITE_P(PoweredStates, RSM05_EstopPriority, ::testing::Range(0, 7));

TEST(RSM05_Estop, EstopInIdleAndResetNeededAlsoEntersEstopActive) {
  Rig r;
  r.boot();
  r.in.estop_closed.a = false;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::EstopActive);
  r.in.estop_closed.a = true;
  r.cycle();
  ASSERT_EQ(r.state(), StateId::EstopResetNeeded);
  r.in.estop_closed.b = false;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::EstopActive);
}

TEST(RSM05_Estop, ReleasingEntersResetNeededNeverIdle) {
  Rig r;
  r.to_reset_needed();
  EXPECT_TRUE(r.out.reset_lamp);
  r.cycles(1000);
  EXPECT_EQ(r.state(), StateId::EstopResetNeeded);
  EXPECT_TRUE(r.out.reset_lamp);
}

TEST(RSM05_Estop, ResetWhilePressedIsRejectedAndChangesNothing) {
  Rig r;
  r.boot();
  r.in.estop_closed = {false, false};
  r.cycle();
  const StatusRecord before = r.st();
  EXPECT_EQ(r.command(Command::reset()), CommandResult::rejected(RejectReason::EstopPressed));
  EXPECT_EQ(r.command_row(), "K02");
  EXPECT_EQ(r.state(), StateId::EstopActive);
  EXPECT_EQ(without_command_fields(r.st()), without_command_fields(before));
  EXPECT_EQ(r.st().last_reject_reason, RejectReason::EstopPressed);
}

TEST(RSM05_Estop, ResetWithOneChannelStillOpenIsRejected) {
  Rig r;
  r.boot();
  r.in.estop_closed = {false, false};
  r.cycle();
  r.in.estop_closed = {true, false};  // half released: still tripped (1oo2)
  EXPECT_EQ(r.command(Command::reset()), CommandResult::rejected(RejectReason::EstopPressed));
  EXPECT_EQ(r.state(), StateId::EstopActive);
}

TEST(RSM05_Estop, ResetAfterReleaseEntersIdleWithLampOff) {
  Rig r;
  r.to_reset_needed();
  EXPECT_EQ(r.command(Command::reset()), CommandResult::accepted());
  EXPECT_EQ(r.command_row(), "K05");
  EXPECT_EQ(r.state(), StateId::Idle);
  EXPECT_FALSE(r.out.reset_lamp);
}

TEST(RSM05_Estop, ResetWithDriveFaultIsRejected) {
  Rig r;
  r.to_reset_needed();
  r.plant.drive_fault = true;
  EXPECT_EQ(r.command(Command::reset()), CommandResult::rejected(RejectReason::DriveFault));
  EXPECT_EQ(r.state(), StateId::EstopResetNeeded);
}

TEST(RSM05_Estop, ResetOutsideResetNeededIsWrongState) {
  Rig r;
  r.boot();
  EXPECT_EQ(r.command(Command::reset()), CommandResult::rejected(RejectReason::WrongState));
  EXPECT_EQ(r.command_row(), "K03");
  EXPECT_EQ(r.state(), StateId::Idle);
}

TEST(RSM05_Estop, EstopWinsOverACommandOfTheSameCycle) {
  Rig r;
  r.to_operational(SelectorReading::Auto);
  ASSERT_EQ(r.submit(Command::start()), SubmitResult::queued);
  r.in.estop_closed.a = false;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::EstopActive);
  EXPECT_EQ(r.st().command_result, CommandResult::rejected(RejectReason::WrongState));
}

// ---------------------------------------------------------------- RSM-04 dual channels

TEST(RSM04_DualChannelInput, EitherChannelTripsTheFunction) {
  DualChannelInput<bool> in(50);
  in.update({true, true});
  EXPECT_FALSE(in.tripped());
  in.update({false, true});
  EXPECT_TRUE(in.tripped());
  in.update({true, false});
  EXPECT_TRUE(in.tripped());
  in.update({false, false});
  EXPECT_TRUE(in.tripped());
}

TEST(RSM04_DualChannelInput, CounterCountsDisagreementSaturatesAtDPlusOneAndResetsOnAgreement) {
  DualChannelInput<bool> in(3);
  for (std::uint32_t i = 1; i <= 3; ++i) {
    in.update({true, false});
    EXPECT_EQ(in.mismatch_cycles(), i);
    EXPECT_FALSE(in.discrepancy_fault());
  }
  in.update({true, false});
  EXPECT_EQ(in.mismatch_cycles(), 4U);
  EXPECT_TRUE(in.discrepancy_fault());
  in.update({false, true});
  EXPECT_EQ(in.mismatch_cycles(), 4U);  // saturated at D + 1
  in.update({false, false});
  EXPECT_EQ(in.mismatch_cycles(), 0U);
  EXPECT_FALSE(in.discrepancy_fault());
}

TEST(RSM04_DualChannelInput, EnablingDeviceMiddleOnBothChannelsIsTheOnlyHealthyReading) {
  DualChannelInput<EnablePosition> e(50);
  e.update({EnablePosition::Middle, EnablePosition::Middle});
  EXPECT_FALSE(e.tripped());
  EXPECT_TRUE(e.both(EnablePosition::Middle));
  e.update({EnablePosition::Middle, EnablePosition::Panic});
  EXPECT_TRUE(e.tripped());
  EXPECT_TRUE(e.either(EnablePosition::Panic));
  EXPECT_EQ(e.mismatch_cycles(), 1U);
  e.update({EnablePosition::Released, EnablePosition::Released});
  EXPECT_TRUE(e.tripped());
  EXPECT_EQ(e.mismatch_cycles(), 0U);
}

TEST(RSM04_DualChannelInput, HugeDiscrepancyTimeDoesNotWrapTheCounter) {
  DualChannelInput<bool> in(0xFFFF'FFFFU);
  for (int i = 0; i < 10; ++i) in.update({true, false});
  EXPECT_EQ(in.mismatch_cycles(), 10U);
  EXPECT_FALSE(in.discrepancy_fault());
}

struct DiscrepancyCase {
  const char* name;
  FaultCode code;
  void (*disagree)(ScanInputs&);
};

// Printed by name (gtest would otherwise dump the struct's bytes, padding included).
void PrintTo(const DiscrepancyCase& c, std::ostream* os) { *os << c.name; }

class RSM04_Discrepancy : public ::testing::TestWithParam<DiscrepancyCase> {};

TEST_P(RSM04_Discrepancy, ExactlyDCyclesAreToleratedAndTheNextLatchesLockout) {
  Config c = flange_config();
  c.discrepancy_cycles = 50;
  Rig r(c);
  r.to_operational(SelectorReading::T1);
  ScanInputs disagreeing = r.in;
  GetParam().disagree(disagreeing);
  r.in = disagreeing;
  r.cycles(50);
  EXPECT_NE(r.state(), StateId::ErrorLockout) << "D mismatching cycles are tolerated";
  r.cycle();
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, GetParam().code);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_EQ(r.cycle_row(), "C03");
  EXPECT_FALSE(r.out.contactor_closed);
}

TEST_P(RSM04_Discrepancy, AgreementWithinDCyclesRestartsTheCount) {
  Rig r;
  r.boot(SelectorReading::T1);
  const ScanInputs healthy_in = r.in;
  ScanInputs disagreeing = r.in;
  GetParam().disagree(disagreeing);
  for (int round = 0; round < 5; ++round) {
    r.in = disagreeing;
    r.cycles(50);
    r.in = healthy_in;
    r.cycle();
  }
  EXPECT_NE(r.state(), StateId::ErrorLockout);
}

INSTANTIATE_TEST_SUITE_P(Inputs, RSM04_Discrepancy,
                         ::testing::Values(DiscrepancyCase{"Estop", FaultCode::DiscrepancyEstop,
                                                           [](ScanInputs& in) { in.estop_closed.a = false; }},
                                           DiscrepancyCase{"Safeguard", FaultCode::DiscrepancySafeguard,
                                                           [](ScanInputs& in) { in.safeguard_closed.b = false; }},
                                           DiscrepancyCase{
                                               "Enabling", FaultCode::DiscrepancyEnabling,
                                               [](ScanInputs& in) { in.enabling.a = EnablePosition::Released; }},
                                           DiscrepancyCase{"Selector", FaultCode::SelectorInvalid,
                                                           [](ScanInputs& in) { in.selector.auto_ = true; }}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(RSM04_Discrepancy, StuckEstopChannelTripsAtOnceAndLatchesAfterDPlusOneCycles) {
  Rig r;
  r.to_auto_running();
  r.in.estop_closed.b = false;  // channel B stuck open, A still closed
  r.cycle();
  EXPECT_EQ(r.state(), StateId::EstopActive);  // same cycle (C06)
  r.cycles(49);
  EXPECT_EQ(r.state(), StateId::EstopActive);
  EXPECT_EQ(r.st().estop_mismatch, 50U);
  r.cycle();
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::DiscrepancyEstop);
}

TEST(RSM04_Discrepancy, CodesAreCheckedInTheDocumentedOrder) {
  Rig r;
  r.boot(SelectorReading::T1);
  r.in.safeguard_closed.a = false;
  r.in.enabling.b = EnablePosition::Panic;
  r.in.estop_closed.a = false;
  r.cycles(51);
  EXPECT_EQ(r.st().fault_code, FaultCode::DiscrepancyEstop);

  Rig r2;
  r2.boot(SelectorReading::T1);
  r2.in.enabling.b = EnablePosition::Panic;
  r2.in.safeguard_closed.a = false;
  r2.in.selector = contacts(SelectorReading::Invalid);
  r2.cycles(51);
  EXPECT_EQ(r2.st().fault_code, FaultCode::DiscrepancySafeguard);
}

TEST(RSM04_Discrepancy, CountersRunInBootAndInLockout) {
  Config c = flange_config();
  c.discrepancy_cycles = 0;  // no tolerance: the first disagreement latches
  Rig r(c);
  r.in = healthy();
  r.in.estop_closed.a = false;
  r.cycle();  // BOOT: C02 does not hold, C03 does
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::DiscrepancyEstop);
  r.in = healthy();
  r.in.safeguard_closed.a = false;
  r.cycles(3);
  EXPECT_EQ(r.st().safeguard_mismatch, 1U);  // saturated at D + 1 = 1
  EXPECT_EQ(r.st().estop_mismatch, 0U);
  EXPECT_EQ(r.st().fault_code, FaultCode::DiscrepancyEstop);  // the first fault stays
}

TEST(RSM04_Discrepancy, LockoutIsNeverLeftEvenWhenChannelsAgreeAndEveryCommandIsSent) {
  Rig r;
  r.boot();
  r.in.estop_closed.a = false;
  r.cycles(51);
  ASSERT_EQ(r.state(), StateId::ErrorLockout);
  r.in = healthy();
  const Command all[] = {Command::reset(),     Command::servo_on(), Command::servo_off(),         Command::start(),
                         Command::pause(),     Command::resume(),   Command::jog_start(1, 1, 10), Command::jog_stop(),
                         Command::t2_confirm()};
  for (const Command& c : all) {
    EXPECT_EQ(r.command(c), CommandResult::rejected(RejectReason::LockedOut));
    EXPECT_EQ(r.command_row(), "K01");
  }
  r.cycles(10000);
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.cycle_row(), "C01");
  EXPECT_FALSE(r.out.contactor_closed);
}

TEST(RSM04_Discrepancy, BouncingEstopNeverLatchesButAlwaysNeedsReset) {
  Rig r;
  r.to_auto_running();
  // Contact bounce: channel A chatters for a few cycles at a time, never 51 in a row.
  for (int i = 0; i < 200; ++i) {
    r.in.estop_closed.a = (i % 7) >= 3;
    r.cycle();
    EXPECT_NE(r.state(), StateId::ErrorLockout);
    EXPECT_FALSE(is_motion(r.state()));
  }
  r.in.estop_closed = {true, true};
  r.cycle();
  EXPECT_EQ(r.state(), StateId::EstopResetNeeded);
  EXPECT_EQ(r.command(Command::start()), CommandResult::rejected(RejectReason::WrongState));
}

// ---------------------------------------------------------------- RSM-02 mode selector

TEST(RSM02_ModeSelector, ExactlyOneClosedContactIsAValidReading) {
  EXPECT_EQ(contacts(SelectorReading::Auto).reading(), SelectorReading::Auto);
  EXPECT_EQ(contacts(SelectorReading::T1).reading(), SelectorReading::T1);
  EXPECT_EQ(contacts(SelectorReading::T2).reading(), SelectorReading::T2);
  EXPECT_EQ((SelectorContacts{false, false, false}.reading()), SelectorReading::Invalid);
  EXPECT_EQ((SelectorContacts{true, true, false}.reading()), SelectorReading::Invalid);
  EXPECT_EQ((SelectorContacts{false, true, true}.reading()), SelectorReading::Invalid);
  EXPECT_EQ((SelectorContacts{true, true, true}.reading()), SelectorReading::Invalid);
}

TEST(RSM02_ModeSelector, InvalidCounterCountsSaturatesAndClears) {
  ModeSelector sel(2);
  EXPECT_EQ(sel.reading(), SelectorReading::Invalid);
  sel.update({true, true, false});
  sel.update({true, true, false});
  EXPECT_FALSE(sel.invalid_fault());
  sel.update({false, false, false});
  EXPECT_TRUE(sel.invalid_fault());
  sel.update({false, false, false});
  EXPECT_EQ(sel.invalid_cycles(), 3U);
  sel.update({false, true, false});
  EXPECT_EQ(sel.reading(), SelectorReading::T1);
  EXPECT_EQ(sel.invalid_cycles(), 0U);
}

TEST(RSM02_ModeSelector, ModeChangeWhilePoweredStopsCat1AndMotionNeedsANewServoOn) {
  Rig r;
  r.to_auto_running();
  r.in = healthy(SelectorReading::T1);
  r.in.qd = kSlow;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.cycle_row(), "C12");
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);
  EXPECT_TRUE(r.out.ramp_down_request);
  EXPECT_TRUE(r.out.contactor_closed);  // Cat 1: power kept while ramping down
  r.in.qd = kRest;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle);
  EXPECT_FALSE(r.out.contactor_closed);
  EXPECT_EQ(r.command(Command::jog_start(1, 1, 10)), CommandResult::rejected(RejectReason::WrongState));
  r.plant.servo_ready = false;
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
  EXPECT_EQ(r.st().session_mode, OperatingMode::T1);
}

TEST(RSM02_ModeSelector, InvalidReadingWhilePoweredStopsCat1) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  r.in.selector = contacts(SelectorReading::Invalid);
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);
  EXPECT_EQ(r.st().selector, SelectorReading::Invalid);
}

TEST(RSM02_ModeSelector, InvalidReadingLongerThanDiscrepancyTimeLatchesLockout) {
  Rig r;
  r.boot();
  r.in.selector = {true, false, true};
  r.cycles(50);
  EXPECT_EQ(r.state(), StateId::Idle);
  EXPECT_EQ(r.st().selector_invalid, 50U);
  r.cycle();
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::SelectorInvalid);
}

TEST(RSM02_ModeSelector, ACat1StopInProgressIsNotRestartedByAFurtherModeChange) {
  Rig r;
  r.to_auto_running();
  r.in.safeguard_closed.a = r.in.safeguard_closed.b = false;
  r.cycle();
  ASSERT_EQ(r.state(), StateId::Stopping);
  r.cycle();
  EXPECT_EQ(r.st().state_cycles, 1U);
  r.in.selector = contacts(SelectorReading::T2);
  r.cycle();
  EXPECT_EQ(r.cycle_row(), "C21");  // not C12 again
  EXPECT_EQ(r.st().state_cycles, 2U);
}

// ---------------------------------------------------------------- RSM-03 stop categories

TEST(RSM03_StopCategories, EstopIsCat0PowerAndBrakesInTheSameCycle) {
  Rig r;
  r.to_auto_running();
  r.in.estop_closed = {false, false};
  r.in.qd = kSlow;  // even while moving
  r.cycle();
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_FALSE(r.out.contactor_closed);
  EXPECT_FALSE(r.out.brake_release);
}

TEST(RSM03_StopCategories, SafeguardOpenedInAutoIsCat1PowerKeptUntilStandstill) {
  Rig r;
  r.to_auto_running();
  r.in.safeguard_closed.a = false;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);
  for (int i = 0; i < 20; ++i) {
    r.cycle();  // still moving: power kept, ramp-down requested
    EXPECT_TRUE(r.out.contactor_closed);
    EXPECT_TRUE(r.out.ramp_down_request);
  }
  r.in.qd = kRest;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle);
  EXPECT_FALSE(r.out.contactor_closed);
  EXPECT_FALSE(r.out.brake_release);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);  // kept after the stop completed
}

TEST(RSM03_StopCategories, PauseIsCat2PowerKeptAndPositionHeld) {
  Rig r;
  r.to_hold();
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat2);
  EXPECT_TRUE(r.out.contactor_closed);
  EXPECT_TRUE(r.out.brake_release);
  EXPECT_FALSE(r.out.ramp_down_request);
  for (const AxisState a : r.out.axes) EXPECT_EQ(a, AxisState::StandStill);
}

TEST(RSM03_StopCategories, ServoOnClearsTheStopCategory) {
  Rig r;
  r.to_reset_needed();
  ASSERT_EQ(r.st().stop_category, StopCategory::Cat0);
  (void)r.command(Command::reset());
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat0);
  EXPECT_EQ(r.command(Command::servo_on()), CommandResult::accepted());
  EXPECT_EQ(r.st().stop_category, StopCategory::None);
}

TEST(RSM03_StopCategories, ServoOffIsCat1) {
  Rig r;
  r.to_operational(SelectorReading::Auto);
  EXPECT_EQ(r.command(Command::servo_off()), CommandResult::accepted());
  EXPECT_EQ(r.state(), StateId::Stopping);
  EXPECT_EQ(r.st().stop_category, StopCategory::Cat1);
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle);
}

}  // namespace
