// SPDX-License-Identifier: Apache-2.0
// Why a Config is invalid (design §9; an invalid Config fails the BOOT self-test, C02).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

enum class ConfigError : std::uint8_t {
  None,
  CycleTimeZero,               ///< cycle_time_us must be > 0
  DiscrepancyTooLarge,         ///< discrepancy_cycles above kMaxTimerCycles
  ArmingTimeoutTooLarge,       ///< arming_timeout_cycles above kMaxTimerCycles
  MaxStopTooLarge,             ///< max_stop_cycles above kMaxTimerCycles
  T1LimitNotPositive,          ///< t1_speed_limit_mm_s must be > 0
  ZeroVelocityInvalid,         ///< zero_velocity_rad_s must be finite and >= 0
  QueueLimitOutOfRange,        ///< command_queue_limit must be in 1..kMaxQueueCapacity
  DhTableNotFinite,            ///< every DH parameter (and the tool offset) must be a finite number
  T1LimitAboveReducedSpeed,    ///< t1_speed_limit_mm_s above 250 mm/s (ISO 10218-1 reduced speed)
  T2LimitOutOfRange,           ///< t2_speed_limit_mm_s must be in (t1 limit, kMaxT2SpeedLimitMmS]
  StandstillWindowOutOfRange,  ///< standstill_speed_window_mm_s must be in (0, t1 limit)
  ToolOffsetNotGiven,          ///< tool_offset_m must be stated (kFlangeTcp for no tool)
  ZeroVelocityAboveWindow,     ///< zero_velocity_rad_s seen at the tool exceeds the standstill window
  FieldbusWorkingCounterZero,  ///< fieldbus_expected_working_counter must be > 0 (0 accepts silence)
  FieldbusToleranceTooLarge,   ///< fieldbus_lost_cycles_limit above kMaxFieldbusLostCycles
  T2ConfirmTimeoutOutOfRange,  ///< t2_confirm_timeout_cycles must be in 1..kMaxTimerCycles
  FeedbackTimeTooLarge,        ///< feedback_allowed_cycles above kMaxFeedbackCycles
};

inline constexpr std::size_t kConfigErrorCount = 18;

inline constexpr std::array<ConfigError, kConfigErrorCount> kAllConfigErrors{
    ConfigError::None,
    ConfigError::CycleTimeZero,
    ConfigError::DiscrepancyTooLarge,
    ConfigError::ArmingTimeoutTooLarge,
    ConfigError::MaxStopTooLarge,
    ConfigError::T1LimitNotPositive,
    ConfigError::ZeroVelocityInvalid,
    ConfigError::QueueLimitOutOfRange,
    ConfigError::DhTableNotFinite,
    ConfigError::T1LimitAboveReducedSpeed,
    ConfigError::T2LimitOutOfRange,
    ConfigError::StandstillWindowOutOfRange,
    ConfigError::ToolOffsetNotGiven,
    ConfigError::ZeroVelocityAboveWindow,
    ConfigError::FieldbusWorkingCounterZero,
    ConfigError::FieldbusToleranceTooLarge,
    ConfigError::T2ConfirmTimeoutOutOfRange,
    ConfigError::FeedbackTimeTooLarge,
};

[[nodiscard]] constexpr std::string_view to_string(ConfigError e) noexcept {
  switch (e) {
    case ConfigError::None: return "NONE";
    case ConfigError::CycleTimeZero: return "CYCLE_TIME_ZERO";
    case ConfigError::DiscrepancyTooLarge: return "DISCREPANCY_TOO_LARGE";
    case ConfigError::ArmingTimeoutTooLarge: return "ARMING_TIMEOUT_TOO_LARGE";
    case ConfigError::MaxStopTooLarge: return "MAX_STOP_TOO_LARGE";
    case ConfigError::T1LimitNotPositive: return "T1_LIMIT_NOT_POSITIVE";
    case ConfigError::ZeroVelocityInvalid: return "ZERO_VELOCITY_INVALID";
    case ConfigError::QueueLimitOutOfRange: return "QUEUE_LIMIT_OUT_OF_RANGE";
    case ConfigError::DhTableNotFinite: return "DH_TABLE_NOT_FINITE";
    case ConfigError::T1LimitAboveReducedSpeed: return "T1_LIMIT_ABOVE_REDUCED_SPEED";
    case ConfigError::T2LimitOutOfRange: return "T2_LIMIT_OUT_OF_RANGE";
    case ConfigError::StandstillWindowOutOfRange: return "STANDSTILL_WINDOW_OUT_OF_RANGE";
    case ConfigError::ToolOffsetNotGiven: return "TOOL_OFFSET_NOT_GIVEN";
    case ConfigError::ZeroVelocityAboveWindow: return "ZERO_VELOCITY_ABOVE_WINDOW";
    case ConfigError::FieldbusWorkingCounterZero: return "FIELDBUS_WORKING_COUNTER_ZERO";
    case ConfigError::FieldbusToleranceTooLarge: return "FIELDBUS_TOLERANCE_TOO_LARGE";
    case ConfigError::T2ConfirmTimeoutOutOfRange: return "T2_CONFIRM_TIMEOUT_OUT_OF_RANGE";
    case ConfigError::FeedbackTimeTooLarge: return "FEEDBACK_TIME_TOO_LARGE";
  }
  return "?";
}

}  // namespace safestate
