// SPDX-License-Identifier: Apache-2.0
// UCA-RSM-16 of the design page's hazard analysis (§13): a ramped stop removes power only
// once the arm is measured at standstill, or for a Cat 0 cause of that cycle (a fault shown,
// an E-stop, PANIC). The C++ driven the way the model's UCA_STOP_POWER_AT_STANDSTILL says,
// asserted over the inputs and the outputs.
#include <gtest/gtest.h>

#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT: test code

bool powered(const ScanOutputs& out) { return out.contactor_closed && out.drive_enable && out.brake_release; }
bool unpowered(const ScanOutputs& out) { return !out.contactor_closed && !out.drive_enable && !out.brake_release; }

/// Cycles `n` times with the arm still moving: every cycle keeps the ramp-down request and
/// all three power outputs on.
void expect_ramp_powered_while_moving(Rig& r, int n) {
  r.in.qd = kSlow;
  for (int i = 0; i < n; ++i) {
    r.cycle();
    ASSERT_TRUE(r.out.ramp_down_request) << "cycle " << i << ": " << describe(r.st());
    ASSERT_TRUE(powered(r.out)) << "cycle " << i << ": power removed while the arm moves, " << describe(r.st());
  }
}

/// AUTO_RUNNING with the arm moving, then the safeguard opened on both channels: a Cat 1
/// ramp (C13) with power on.
void to_cat1_ramp_in_auto(Rig& r) {
  r.to_auto_running();
  r.in.safeguard_closed = {false, false};
  r.cycle();
  ASSERT_EQ(r.state(), StateId::Stopping);
  ASSERT_EQ(r.st().stop_category, StopCategory::Cat1);
  ASSERT_TRUE(powered(r.out));
}

// UCA-RSM-16: the safeguard opened in AUTO with the arm moving: a Cat 1 ramp keeps power on
// through every cycle that measures motion, and the first cycle that measures standstill
// removes it, with no fault.
// req: RSM-08 RSM-11
TEST(UCA_RSM_16_StopPowerAtStandstill, ACat1StopInAutoKeepsPowerUntilTheArmIsAtStandstill) {
  Rig r;
  to_cat1_ramp_in_auto(r);
  expect_ramp_powered_while_moving(r, 50);
  r.in.qd = kRest;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle) << describe(r.st());
  EXPECT_TRUE(unpowered(r.out));
  EXPECT_EQ(r.st().fault_code, FaultCode::None);
}

// UCA-RSM-16: the enabling device released during a T1 jog (C14, Cat 1): power stays on
// while the jogged axis still turns, and goes at standstill.
// req: RSM-09 RSM-11
TEST(UCA_RSM_16_StopPowerAtStandstill, ACat1StopFromTheEnablingDeviceKeepsPowerUntilStandstill) {
  Rig r;
  r.to_jogging(SelectorReading::T1);
  r.in.enabling = {EnablePosition::Released, EnablePosition::Released};
  r.cycle();
  ASSERT_EQ(r.state(), StateId::Stopping);
  ASSERT_EQ(r.st().stop_category, StopCategory::Cat1);
  expect_ramp_powered_while_moving(r, 20);
  r.in.qd = kRest;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::Idle) << describe(r.st());
  EXPECT_TRUE(unpowered(r.out));
}

// UCA-RSM-16 with RSM-11's budget: an arm still moving when the stop timer expires is not
// quietly unpowered as if it had stopped: the cycle that removes power shows STOP_TIMEOUT.
// req: RSM-11 RSM-03
TEST(UCA_RSM_16_StopPowerAtStandstill, AnArmStillMovingAtTheStopBudgetIsUnpoweredOnlyWithAFaultShown) {
  Config c = flange_config();
  c.max_stop_cycles = 5;
  Rig r(c);
  to_cat1_ramp_in_auto(r);
  r.in.qd = kSlow;
  int cycles = 0;
  do {
    r.cycle();
    ++cycles;
    ASSERT_LE(cycles, 10) << describe(r.st());
  } while (powered(r.out));
  EXPECT_TRUE(unpowered(r.out));
  EXPECT_EQ(r.state(), StateId::ErrorLockout);
  EXPECT_EQ(r.st().fault_code, FaultCode::StopTimeout) << describe(r.st());
}

// UCA-RSM-16: an E-stop during the ramp is a Cat 0 cause: power goes in that cycle, moving
// or not (the exception the property names).
// req: RSM-05 RSM-03
TEST(UCA_RSM_16_StopPowerAtStandstill, AnEstopDuringTheRampRemovesPowerAtOnce) {
  Rig r;
  to_cat1_ramp_in_auto(r);
  r.in.estop_closed = {false, false};
  r.in.qd = kSlow;
  r.cycle();
  EXPECT_EQ(r.state(), StateId::EstopActive);
  EXPECT_TRUE(unpowered(r.out));
}

}  // namespace
