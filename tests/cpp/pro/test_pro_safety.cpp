// GoogleTest of ao_safety + sm_protection, one suite per requirement (PRO-01..04),
// against docs/design/protection.md §3-§5.
#include <gtest/gtest.h>

#include <cstdint>

#include "safestate/pro/ao_safety.hpp"

namespace {

using safestate::pro::AoSafety;
using safestate::pro::FaultCause;
using safestate::pro::ProtectionState;
using safestate::pro::SafetyResult;
using safestate::pro::SensorSnapshot;

SensorSnapshot reading(std::int16_t temp_c, std::uint16_t volt_dv, bool valid = true, bool clear = false) {
  return SensorSnapshot{temp_c, volt_dv, valid, clear};
}

constexpr SensorSnapshot kNominal{40, 240, true, false};

TEST(PRO01_HazardEvaluation, EachLimitIsStrict) {
  AoSafety safety;
  EXPECT_EQ(safety.hazard_cause(reading(85, 180)), FaultCause::none);
  EXPECT_EQ(safety.hazard_cause(reading(85, 300)), FaultCause::none);
  EXPECT_EQ(safety.hazard_cause(reading(86, 240)), FaultCause::over_temperature);
  EXPECT_EQ(safety.hazard_cause(reading(40, 179)), FaultCause::under_voltage);
  EXPECT_EQ(safety.hazard_cause(reading(40, 301)), FaultCause::over_voltage);
  EXPECT_EQ(safety.hazard_cause(reading(40, 240, false)), FaultCause::sensor_invalid);
}

TEST(PRO01_HazardEvaluation, InvalidSensorIsReportedBeforeItsReadings) {
  AoSafety safety;
  EXPECT_EQ(safety.hazard_cause(reading(120, 100, false)), FaultCause::sensor_invalid);
}

TEST(PRO01_HazardEvaluation, OneHazardousSnapshotEntersProtection) {
  AoSafety safety;
  EXPECT_EQ(safety.dispatch(kNominal, 1), SafetyResult::ok);
  EXPECT_EQ(safety.dispatch(reading(40, 310), 2), SafetyResult::protection_entered);
  EXPECT_EQ(safety.context().protection_state, ProtectionState::protection);
  EXPECT_EQ(safety.context().last_transition_tick, 2U);
  EXPECT_EQ(safety.last_fault_event(), FaultCause::over_voltage);
}

TEST(PRO02_Latch, ProtectionStaysAfterTheHazardIsGone) {
  AoSafety safety;
  ASSERT_EQ(safety.dispatch(reading(90, 240), 1), SafetyResult::protection_entered);
  EXPECT_EQ(safety.dispatch(kNominal, 2), SafetyResult::ok);
  EXPECT_EQ(safety.context().protection_state, ProtectionState::protection);
  EXPECT_TRUE(safety.context().latch_active);
  EXPECT_EQ(safety.context().last_transition_tick, 1U);
}

TEST(PRO02_Latch, ClearWhileHotIsBlockedAndClearWhenCoolIsAccepted) {
  AoSafety safety;
  ASSERT_EQ(safety.dispatch(reading(90, 240), 1), SafetyResult::protection_entered);
  EXPECT_EQ(safety.dispatch(reading(90, 240, true, true), 2), SafetyResult::latch_blocked);
  EXPECT_EQ(safety.last_fault_event(), FaultCause::latch_blocked);
  EXPECT_EQ(safety.context().protection_state, ProtectionState::protection);
  EXPECT_EQ(safety.dispatch(reading(85, 240, true, true), 3), SafetyResult::ok);
  EXPECT_EQ(safety.context().protection_state, ProtectionState::normal);
  EXPECT_FALSE(safety.context().latch_active);
  EXPECT_FALSE(safety.context().override_active);
  EXPECT_EQ(safety.context().last_transition_tick, 3U);
}

TEST(PRO02_Latch, ClearInTheEntryTickIsNoClear) {
  AoSafety safety;
  EXPECT_EQ(safety.dispatch(reading(40, 240, false, true), 1), SafetyResult::protection_entered);
  EXPECT_EQ(safety.context().protection_state, ProtectionState::protection);
}

TEST(PRO03_Override, FanIsAtTheSafeValueExactlyWhileProtected) {
  AoSafety safety;
  EXPECT_EQ(safety.fan_output(30), 30);
  ASSERT_EQ(safety.dispatch(reading(40, 170), 1), SafetyResult::protection_entered);
  EXPECT_EQ(safety.fan_output(30), safestate::pro::kSafeFanCommandPercent);
  EXPECT_TRUE(safety.context().override_active);
  ASSERT_EQ(safety.dispatch(reading(40, 240, true, true), 2), SafetyResult::ok);
  EXPECT_EQ(safety.fan_output(30), 30);
}

TEST(PRO04_Response, ProtectionInTheTickOfTheFirstHazardousSnapshot) {
  // The design's response is one tick (100 ms) from the first hazardous snapshot, far
  // inside the 10-tick budget: no hazardous snapshot ever leaves the fan regulated.
  AoSafety safety;
  for (std::uint32_t tick = 1; tick <= 200; ++tick) {
    const bool hot = (tick / 7) % 3 == 1;
    const SensorSnapshot s = reading(hot ? 95 : 50, 240, true, tick % 5 == 0);
    (void)safety.dispatch(s, tick);
    if (hot) {
      EXPECT_EQ(safety.fan_output(0), safestate::pro::kSafeFanCommandPercent) << tick;
    }
  }
}

}  // namespace

namespace {

// Issue 31 item 5: the event's hazard_detected, the outputs_disabled state and the
// degraded mode (docs/design/protection.md §2-§4a).
TEST(PRO01_HazardDetected, TheEventsHazardFlagAloneEntersProtectionWithItsCause) {
  AoSafety safety;
  SensorSnapshot s = kNominal;
  s.hazard_detected = true;
  EXPECT_EQ(safety.hazard_cause(s), FaultCause::hazard_detected);
  EXPECT_EQ(safety.dispatch(s, 1), SafetyResult::protection_entered);
  EXPECT_EQ(safety.last_fault_event(), FaultCause::hazard_detected);
  s.temperature_c = 90;  // a measured cause is reported before the flag
  EXPECT_EQ(safety.hazard_cause(s), FaultCause::over_temperature);
}

TEST(PRO03_OutputsDisabled, ProtectionRemovesThePermissiveAndForcesTheSafeFanValue) {
  AoSafety safety;
  ASSERT_EQ(safety.dispatch(kNominal, 1), SafetyResult::ok);
  EXPECT_TRUE(safety.load_enable());
  EXPECT_EQ(safety.fan_output(40), 40);
  ASSERT_EQ(safety.dispatch(reading(90, 240), 2), SafetyResult::protection_entered);
  EXPECT_FALSE(safety.load_enable());
  EXPECT_EQ(safety.fan_output(100), safestate::pro::kSafeFanCommandPercent);  // regulation's own 100 % is no protection
  EXPECT_EQ(safety.fan_output(40), safestate::pro::kSafeFanCommandPercent);
}

TEST(PRO02_Latch, InDegradedAClearWithoutAHazardIsDeniedAndRecoveryDoesNotClear) {
  AoSafety safety;
  ASSERT_EQ(safety.dispatch(reading(90, 240), 1), SafetyResult::protection_entered);
  safety.set_degraded(true);  // EVT_DEGRADED
  EXPECT_EQ(safety.dispatch(reading(40, 240, true, true), 2), SafetyResult::latch_blocked);
  EXPECT_EQ(safety.last_fault_event(), FaultCause::latch_blocked);
  safety.set_degraded(false);  // EVT_RECOVERY
  EXPECT_EQ(safety.dispatch(kNominal, 3), SafetyResult::ok);
  EXPECT_EQ(safety.context().protection_state, ProtectionState::protection);  // still latched
  EXPECT_FALSE(safety.load_enable());
  EXPECT_EQ(safety.dispatch(reading(40, 240, true, true), 4), SafetyResult::ok);
  EXPECT_EQ(safety.context().protection_state, ProtectionState::normal);
  EXPECT_TRUE(safety.load_enable());
}

TEST(PRO01_HazardDetected, InDegradedAHazardStillEntersProtection) {
  AoSafety safety;
  safety.set_degraded(true);
  EXPECT_EQ(safety.dispatch(reading(40, 170), 1), SafetyResult::protection_entered);
}

}  // namespace
