// SPDX-License-Identifier: Apache-2.0
// Issue 29 item 10: the manager reads the drives' CiA 402 status words and supervises the
// fieldbus itself (design §2); these drive the rows that read servo_ready, drive_fault and
// fieldbus_ok (C09, C15, C24) from raw process images, without the simulated master.
#include <gtest/gtest.h>

#include <cstdint>

#include "ssm_test_support.hpp"

namespace {

using namespace ssm_test;  // NOLINT: test code

/// A manager fed raw process images: this test is the EtherCAT master.
class RawBus {
 public:
  RawBus() : m(flange_config()) { words.fill(0x0031); }  // ready to switch on, voltage on

  ScanOutputs cycle() {
    in.bus.status_words = words;
    in.bus.cycle_counter = ++counter;
    in.bus.working_counter = wkc;
    return m.cycle(in);
  }
  ScanOutputs same_frame_again() {
    in.bus.status_words = words;
    in.bus.cycle_counter = counter;
    in.bus.working_counter = wkc;
    return m.cycle(in);
  }

  SystemStateManager m;
  ScanInputs in{healthy(SelectorReading::Auto)};
  DriveStatusWords words{};
  std::uint16_t counter{500};
  std::uint16_t wkc{18};
};

void arm(RawBus& b) {
  b.cycle();
  ASSERT_EQ(b.m.state(), StateId::Idle);
  ASSERT_EQ(b.m.submit(Command::servo_on()), SubmitResult::queued);
  b.cycle();
  ASSERT_EQ(b.m.state(), StateId::Arming);
}

TEST(Issue29_Item10_DriveStatusWords, ArmingEndsWhenTheLastDriveReportsOperationEnabled) {
  RawBus b;
  arm(b);
  for (std::size_t i = 0; i < b.words.size(); ++i) {
    b.words[i] = 0x0037;  // drives enable one after the other
    b.cycle();
    EXPECT_EQ(b.m.state(), i + 1 < b.words.size() ? StateId::Arming : StateId::AutoIdle) << "drive " << i;
  }
  EXPECT_EQ(b.m.last_rows().cycle->id, "C15");
  EXPECT_EQ(b.m.drive_status().drives[5].state, Cia402State::OperationEnabled);
}

TEST(Issue29_Item10_DriveStatusWords, AFaultWordOnAnyDriveWhilePoweredIsADriveFaultLockout) {
  for (std::size_t drive = 0; drive < 6; ++drive) {
    RawBus b;
    arm(b);
    b.words.fill(0x0037);
    b.cycle();
    ASSERT_EQ(b.m.state(), StateId::AutoIdle);
    b.words[drive] = 0x0018;  // Fault (voltage still on)
    const ScanOutputs out = b.cycle();
    EXPECT_EQ(b.m.last_rows().cycle->id, "C09") << "drive " << drive;
    EXPECT_EQ(b.m.status().fault_code, FaultCode::DriveFault);
    EXPECT_FALSE(out.contactor_closed || out.drive_enable || out.brake_release);
  }
}

TEST(Issue29_Item10_DriveStatusWords, AnImplausibleWordIsAFaultAndAWarningIsNot) {
  RawBus b;
  arm(b);
  b.words.fill(0x0037);
  b.words[2] = 0x00B7;  // operation enabled with the warning bit
  b.cycle();
  EXPECT_EQ(b.m.state(), StateId::AutoIdle);
  EXPECT_TRUE(b.m.drive_status().warning);
  b.words[2] = 0x0001;  // matches no CiA 402 state
  b.cycle();
  EXPECT_EQ(b.m.status().fault_code, FaultCode::DriveFault);
}

TEST(Issue29_Item10_DriveStatusWords, AFaultWordBlocksServoOnInIdle) {
  RawBus b;
  b.cycle();
  b.words[4] = 0x0008;
  ASSERT_EQ(b.m.submit(Command::servo_on()), SubmitResult::queued);
  b.cycle();
  EXPECT_EQ(b.m.status().command_result, CommandResult::rejected(RejectReason::DriveFault));
  EXPECT_EQ(b.m.last_rows().command->id, "K07");
}

TEST(Issue29_Item10_FieldbusWatchdogInTheCore, AWrongWorkingCounterLocksOutFromRawFrames) {
  RawBus b;
  arm(b);
  b.wkc = 15;  // one drive missing from the frame
  const ScanOutputs out = b.cycle();
  EXPECT_EQ(b.m.last_rows().cycle->id, "C24");
  EXPECT_EQ(b.m.status().fault_code, FaultCode::FieldbusLoss);
  EXPECT_FALSE(out.contactor_closed);
}

TEST(Issue29_Item10_FieldbusWatchdogInTheCore, AStalledFrameCounterLocksOut) {
  RawBus b;
  b.cycle();
  ASSERT_EQ(b.m.state(), StateId::Idle);
  b.same_frame_again();
  EXPECT_EQ(b.m.status().fault_code, FaultCode::FieldbusLoss);
}

TEST(Issue29_Item10_FieldbusWatchdogInTheCore, AConfiguredToleranceRidesThroughShortGaps) {
  Config c = flange_config();
  c.fieldbus_lost_cycles_limit = 2;
  SystemStateManager m(c);
  ScanInputs in = healthy();
  in.bus.status_words.fill(0x0031);
  in.bus.working_counter = 18;
  in.bus.cycle_counter = 1;
  (void)m.cycle(in);
  (void)m.cycle(in);  // stale 1
  (void)m.cycle(in);  // stale 2
  EXPECT_EQ(m.state(), StateId::Idle);
  in.bus.cycle_counter = 2;
  (void)m.cycle(in);  // fresh: streak over
  EXPECT_EQ(m.fieldbus_watchdog().missed_cycles(), 0U);
  in.bus.cycle_counter = 5;  // two frames skipped: 2 missed, tolerated
  (void)m.cycle(in);
  EXPECT_EQ(m.state(), StateId::Idle);
  (void)m.cycle(in);  // and one stale more: 3 > 2
  EXPECT_EQ(m.status().fault_code, FaultCode::FieldbusLoss);
}

TEST(Issue29_Item10_FieldbusWatchdogInTheCore, ConfigRefusesAZeroWorkingCounterAndALargeTolerance) {
  Config c = flange_config();
  c.fieldbus_expected_working_counter = 0;
  EXPECT_EQ(validate(c), ConfigError::FieldbusWorkingCounterZero);
  c = flange_config();
  c.fieldbus_lost_cycles_limit = kMaxFieldbusLostCycles + 1;
  EXPECT_EQ(validate(c), ConfigError::FieldbusToleranceTooLarge);
  c.fieldbus_lost_cycles_limit = kMaxFieldbusLostCycles;
  EXPECT_EQ(validate(c), ConfigError::None);
}

}  // namespace
