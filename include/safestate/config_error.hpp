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
  CycleTimeZero,          ///< cycle_time_us must be > 0
  DiscrepancyTooLarge,    ///< discrepancy_cycles above kMaxTimerCycles
  ArmingTimeoutTooLarge,  ///< arming_timeout_cycles above kMaxTimerCycles
  MaxStopTooLarge,        ///< max_stop_cycles above kMaxTimerCycles
  T1LimitNotPositive,     ///< t1_speed_limit_mm_s must be > 0
  ZeroVelocityInvalid,    ///< zero_velocity_rad_s must be finite and >= 0
  QueueLimitOutOfRange,   ///< command_queue_limit must be in 1..kMaxQueueCapacity
  DhTableNotFinite,       ///< every DH parameter must be a finite number
};

inline constexpr std::size_t kConfigErrorCount = 9;

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
  }
  return "?";
}

}  // namespace safestate
