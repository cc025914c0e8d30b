// SPDX-License-Identifier: Apache-2.0
// The names the conformance suite compares (design §4–§7) and the parameters of §9.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "safestate/command_kind.hpp"
#include "safestate/command_result.hpp"
#include "safestate/config.hpp"
#include "safestate/config_error.hpp"
#include "safestate/enable_position.hpp"
#include "safestate/enum_strings.hpp"
#include "safestate/fault_code.hpp"
#include "safestate/operating_mode.hpp"
#include "safestate/reject_reason.hpp"
#include "safestate/resume_target.hpp"
#include "safestate/selector_reading.hpp"
#include "safestate/speed_level.hpp"
#include "safestate/state_id.hpp"
#include "safestate/status_record.hpp"
#include "safestate/stop_category.hpp"
#include "safestate/submit_result.hpp"

namespace {

using namespace safestate;  // NOLINT

template <typename E, std::size_t N>
std::vector<std::string> names(const std::array<E, N>& all) {
  std::vector<std::string> out;
  for (const E e : all) {
    out.emplace_back(to_string(e));
    EXPECT_EQ(enum_from_string(to_string(e), all), e);  // round trip
  }
  return out;
}

using V = std::vector<std::string>;

TEST(RSM16_StatusNames, EnumNamesAreTheUpperCaseNamesOfTheDesignPage) {
  EXPECT_EQ(names(kAllStates), (V{"BOOT", "ERROR_LOCKOUT", "ESTOP_ACTIVE", "ESTOP_RESET_NEEDED", "IDLE", "ARMING",
                                  "AUTO_IDLE", "AUTO_RUNNING", "MANUAL_IDLE", "MANUAL_JOGGING", "STOPPING", "HOLD"}));
  EXPECT_EQ(names(kAllEnablePositions), (V{"RELEASED", "MIDDLE", "PANIC"}));
  EXPECT_EQ(names(kAllOperatingModes), (V{"NONE", "AUTO", "T1", "T2"}));
  EXPECT_EQ(names(kAllSelectorReadings), (V{"INVALID", "AUTO", "T1", "T2"}));
  EXPECT_EQ(names(kAllStopCategories), (V{"NONE", "CAT0", "CAT1", "CAT2"}));
  EXPECT_EQ(names(kAllFaultCodes),
            (V{"NONE", "SELF_TEST_FAILED", "DISCREPANCY_ESTOP", "DISCREPANCY_SAFEGUARD", "DISCREPANCY_ENABLING",
               "SELECTOR_INVALID", "DRIVE_FAULT", "T1_OVERSPEED", "ARMING_TIMEOUT", "STOP_TIMEOUT", "FIELDBUS_LOSS",
               "STANDSTILL_VIOLATION", "SERVO_READY_LOST", "T2_OVERSPEED", "CONTACTOR_FEEDBACK", "BRAKE_FEEDBACK"}));
  EXPECT_EQ(names(kAllRejectReasons),
            (V{"NONE", "LOCKED_OUT", "ESTOP_PRESSED", "WRONG_STATE", "DRIVE_FAULT", "SELECTOR_INVALID",
               "SAFEGUARD_OPEN", "ENABLE_NOT_MIDDLE", "T2_NOT_CONFIRMED", "WRONG_MODE", "JOG_IN_AUTO",
               "INVALID_ARGUMENT", "QUEUE_FULL", "CHANNEL_TEST_PENDING"}));
  EXPECT_EQ(names(kAllCommandKinds),
            (V{"RESET", "SERVO_ON", "SERVO_OFF", "START", "PAUSE", "RESUME", "JOG_START", "JOG_STOP", "T2_CONFIRM"}));
  EXPECT_EQ(names(kAllSpeedLevels), (V{"ZERO", "MOVING", "OVER_T1", "OVER_T2"}));
  EXPECT_EQ(names(kAllResumeTargets), (V{"NONE", "AUTO_RUNNING", "MANUAL_JOGGING"}));
  EXPECT_EQ(names(kAllSubmitResults), (V{"QUEUED", "QUEUE_FULL"}));
  EXPECT_EQ(enum_from_string("no such name", kAllStates), std::nullopt);
}

TEST(RSM16_StatusNames, CommandResultIsNoneAcceptedOrTheReason) {
  EXPECT_EQ(to_string(CommandResult::none()), "NONE");
  EXPECT_EQ(to_string(CommandResult::accepted()), "ACCEPTED");
  EXPECT_EQ(to_string(CommandResult::rejected(RejectReason::QueueFull)), "QUEUE_FULL");
}

// A command result is a value: != is exactly the negation of == (the outcome and the
// reason both count).
TEST(RSM13_Commands, CommandResultsDifferExactlyWhenTheyAreNotEqual) {
  const CommandResult all[] = {CommandResult::none(), CommandResult::accepted(),
                               CommandResult::rejected(RejectReason::WrongState),
                               CommandResult::rejected(RejectReason::QueueFull)};
  for (const CommandResult& a : all) {
    for (const CommandResult& b : all) {
      EXPECT_EQ(a != b, !(a == b)) << to_string(a) << " vs " << to_string(b);
      EXPECT_EQ(a == b, &a == &b) << to_string(a) << " vs " << to_string(b);
    }
  }
}

// The status record (RSM-16) compares by every field: tests and the binding use == to
// say "nothing changed", so a field left out of it would hide a change.
template <typename E>
E next_value(E e) {
  return static_cast<E>(static_cast<std::underlying_type_t<E>>(e) + 1);
}

TEST(RSM16_StatusNames, StatusRecordsDifferingInAnyOneFieldAreUnequal) {
  using Change = void (*)(StatusRecord&);
  const Change changes[] = {
      [](StatusRecord& r) { r.state = next_value(r.state); },
      [](StatusRecord& r) { r.selector = next_value(r.selector); },
      [](StatusRecord& r) { r.session_mode = next_value(r.session_mode); },
      [](StatusRecord& r) { r.stop_category = next_value(r.stop_category); },
      [](StatusRecord& r) { r.fault_code = next_value(r.fault_code); },
      [](StatusRecord& r) { r.last_reject_reason = next_value(r.last_reject_reason); },
      [](StatusRecord& r) { r.command_result = CommandResult::accepted(); },
      [](StatusRecord& r) { ++r.estop_mismatch; },
      [](StatusRecord& r) { ++r.safeguard_mismatch; },
      [](StatusRecord& r) { ++r.enabling_mismatch; },
      [](StatusRecord& r) { ++r.selector_invalid; },
      [](StatusRecord& r) { ++r.state_cycles; },
      [](StatusRecord& r) { r.t2_confirmed = !r.t2_confirmed; },
      [](StatusRecord& r) { r.resume_to = next_value(r.resume_to); },
      [](StatusRecord& r) { ++r.jog_axis; },
      [](StatusRecord& r) { ++r.jog_direction; },
      [](StatusRecord& r) { ++r.jog_speed_mm_s; },
      [](StatusRecord& r) { ++r.queue_length; },
      [](StatusRecord& r) { ++r.stale_commands; },
      [](StatusRecord& r) { r.estop_tested_a = !r.estop_tested_a; },
      [](StatusRecord& r) { r.estop_tested_b = !r.estop_tested_b; },
  };
  const StatusRecord base{};
  EXPECT_TRUE(base == StatusRecord{});
  for (std::size_t i = 0; i < std::size(changes); ++i) {
    StatusRecord other{};
    changes[i](other);
    EXPECT_FALSE(base == other) << "field " << i << " of StatusRecord is not compared";
  }
}

TEST(RSM02_OperatingModes, SelectorMatchesSessionOnlyForTheSameValidMode) {
  EXPECT_TRUE(selector_matches(SelectorReading::T1, OperatingMode::T1));
  EXPECT_FALSE(selector_matches(SelectorReading::T2, OperatingMode::T1));
  EXPECT_FALSE(selector_matches(SelectorReading::Invalid, OperatingMode::None));
  EXPECT_TRUE(is_manual(OperatingMode::T2));
  EXPECT_FALSE(is_manual(OperatingMode::Auto));
}

TEST(RSM15_Config, DefaultsAreThoseOfTheDesignPage) {
  const Config c;
  EXPECT_EQ(c.cycle_time_us, 1000U);
  EXPECT_EQ(c.discrepancy_cycles, 50U);
  EXPECT_EQ(c.arming_timeout_cycles, 500U);
  EXPECT_EQ(c.max_stop_cycles, 1000U);
  EXPECT_EQ(c.t1_speed_limit_mm_s, 250);
  EXPECT_DOUBLE_EQ(c.zero_velocity_rad_s, 0.001);
  EXPECT_EQ(c.command_queue_limit, 8U);
  EXPECT_EQ(kMaxQueueCapacity, 16U);
  EXPECT_DOUBLE_EQ(c.dh[1].a_m, kUr5DhTable[1].a_m);
  EXPECT_EQ(c.t2_speed_limit_mm_s, 1000);
  EXPECT_DOUBLE_EQ(c.standstill_speed_window_mm_s, 10.0);
  // Issue 29 item 4: no silent flange default; the defaults become usable once the tool is stated.
  EXPECT_FALSE(c.tool_offset_m.has_value());
  EXPECT_EQ(validate(c), ConfigError::ToolOffsetNotGiven);
  Config stated = c;
  stated.tool_offset_m = kFlangeTcp;
  EXPECT_EQ(validate(stated), ConfigError::None);
}

// kAllConfigErrors is the public list of validate()'s answers: each once, in declaration
// order (as every kAll* list), so that kAllConfigErrors[i] is the error of value i.
TEST(RSM15_Config, EveryConfigErrorIsListedOnceInDeclarationOrder) {
  EXPECT_EQ(names(kAllConfigErrors),
            (V{"NONE", "CYCLE_TIME_ZERO", "DISCREPANCY_TOO_LARGE", "ARMING_TIMEOUT_TOO_LARGE", "MAX_STOP_TOO_LARGE",
               "T1_LIMIT_NOT_POSITIVE", "ZERO_VELOCITY_INVALID", "QUEUE_LIMIT_OUT_OF_RANGE", "DH_TABLE_NOT_FINITE",
               "T1_LIMIT_ABOVE_REDUCED_SPEED", "T2_LIMIT_OUT_OF_RANGE", "STANDSTILL_WINDOW_OUT_OF_RANGE",
               "TOOL_OFFSET_NOT_GIVEN", "ZERO_VELOCITY_ABOVE_WINDOW", "FIELDBUS_WORKING_COUNTER_ZERO",
               "FIELDBUS_TOLERANCE_TOO_LARGE", "T2_CONFIRM_TIMEOUT_OUT_OF_RANGE", "FEEDBACK_TIME_TOO_LARGE"}));
  for (std::size_t i = 0; i < kAllConfigErrors.size(); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(kAllConfigErrors[i]), i) << to_string(kAllConfigErrors[i]);
  }
}

TEST(RSM15_Config, ValidateRejectsEachUnusableParameter) {
  const auto with = [](auto edit) {
    Config c;
    c.tool_offset_m = kFlangeTcp;
    edit(c);
    return validate(c);
  };
  EXPECT_EQ(with([](Config& c) { c.cycle_time_us = 0; }), ConfigError::CycleTimeZero);
  EXPECT_EQ(with([](Config& c) { c.discrepancy_cycles = kMaxTimerCycles + 1U; }), ConfigError::DiscrepancyTooLarge);
  EXPECT_EQ(with([](Config& c) { c.arming_timeout_cycles = 0xFFFF'FFFFU; }), ConfigError::ArmingTimeoutTooLarge);
  EXPECT_EQ(with([](Config& c) { c.max_stop_cycles = 0xFFFF'FFFFU; }), ConfigError::MaxStopTooLarge);
  EXPECT_EQ(with([](Config& c) { c.t1_speed_limit_mm_s = 0; }), ConfigError::T1LimitNotPositive);
  EXPECT_EQ(with([](Config& c) { c.zero_velocity_rad_s = -1e-3; }), ConfigError::ZeroVelocityInvalid);
  EXPECT_EQ(with([](Config& c) { c.zero_velocity_rad_s = std::nan(""); }), ConfigError::ZeroVelocityInvalid);
  EXPECT_EQ(with([](Config& c) { c.command_queue_limit = 0; }), ConfigError::QueueLimitOutOfRange);
  EXPECT_EQ(with([](Config& c) { c.command_queue_limit = 17; }), ConfigError::QueueLimitOutOfRange);
  EXPECT_EQ(with([](Config& c) { c.dh[3].d_m = std::numeric_limits<double>::infinity(); }),
            ConfigError::DhTableNotFinite);
  // Zero-length timers and zero tolerance are meaningful (no tolerance at all), so valid.
  EXPECT_EQ(with([](Config& c) {
              c.discrepancy_cycles = 0;
              c.arming_timeout_cycles = 0;
              c.max_stop_cycles = 0;
              c.zero_velocity_rad_s = 0.0;
            }),
            ConfigError::None);
}

}  // namespace
