// SPDX-License-Identifier: Apache-2.0
// Parameters of the SystemStateManager (design §9): one struct, the model's constants.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "safestate/config_error.hpp"
#include "safestate/dh_table.hpp"
#include "safestate/fieldbus_watchdog.hpp"
#include "safestate/speed_limits.hpp"
#include "safestate/standstill_bound.hpp"

namespace safestate {

/// Compile-time capacity of the command queue; `command_queue_limit` may lower it (§9).
inline constexpr std::size_t kMaxQueueCapacity = 16;

/// Upper bound of the cycle-count parameters, so that every counter (which saturates at the
/// parameter + 1) stays far from overflow. 2^31 - 1 cycles = 24 days at 1 ms.
inline constexpr std::uint32_t kMaxTimerCycles = 0x7FFF'FFFFU;

/// Upper bound of feedback_allowed_cycles: 1 s at 1 ms, beyond any contactor's or brake's
/// switching time, so that a welded contactor is seen long before an operator can act on it.
inline constexpr std::uint32_t kMaxFeedbackCycles = 1000;

struct Config {
  std::uint32_t cycle_time_us{1000};         ///< scan cycle period (informative; timers count cycles)
  std::uint32_t discrepancy_cycles{50};      ///< D: tolerated cycles of channel disagreement (§3)
  std::uint32_t arming_timeout_cycles{500};  ///< cycles ARMING waits for servo_ready (C16)
  std::uint32_t max_stop_cycles{1000};       ///< cycles STOPPING waits for zero speed (C20)
  /// Cycles a T2 confirmation (K35) stays valid for a Servo-on, 1..kMaxTimerCycles (C22).
  std::uint32_t t2_confirm_timeout_cycles{30000};
  std::int32_t t1_speed_limit_mm_s{250};   ///< T1 TCP speed limit, integer mm/s, 1..250 (C10, K29)
  std::int32_t t2_speed_limit_mm_s{1000};  ///< T2 TCP speed limit, integer mm/s (K26)
  double zero_velocity_rad_s{0.001};       ///< |qd[i]| at or below this is standstill (§2)
  /// The TCP speed (mm/s) the standstill class may admit: zero_velocity_rad_s seen at the
  /// tool (zero_class_tcp_bound_mm_s) must not exceed it, and it stays below the T1 limit.
  double standstill_speed_window_mm_s{10.0};
  std::uint32_t command_queue_limit{8};  ///< commands the queue holds, 1..kMaxQueueCapacity
  /// EtherCAT working counter of a complete frame: 3 per drive for the LRW datagram
  /// (read 1 + write 2) of the six drives (§2 "Fieldbus watchdog").
  std::uint16_t fieldbus_expected_working_counter{18};
  /// Missed bus cycles in a row tolerated before C24 (0 = none), at most kMaxFieldbusLostCycles.
  std::uint32_t fieldbus_lost_cycles_limit{0};
  /// Cycles the contactor and brake feedback may disagree with their command (the devices'
  /// switching time, C30), at most kMaxFeedbackCycles.
  std::uint32_t feedback_allowed_cycles{100};
  DhTable dh{kUr5DhTable};  ///< arm kinematics (UR5 standard DH)
  /// Tool centre point in the flange (last DH) frame, metres: the T1 speed (RSM-10) is
  /// measured at the tool tip, not at the flange. No default: the integrator states the
  /// mounted tool (kFlangeTcp for none); a Config without it is invalid (C02).
  std::optional<std::array<double, 3>> tool_offset_m{};
};

/// The tool offset of a tool-less flange, for a Config that states it explicitly.
inline constexpr std::array<double, 3> kFlangeTcp{0.0, 0.0, 0.0};

/// The tool offset the kinematics use: the stated one, the flange for an invalid Config
/// (which never leaves BOOT, C02).
[[nodiscard]] inline std::array<double, 3> tool_offset_or_flange(const Config& c) noexcept {
  return c.tool_offset_m.value_or(kFlangeTcp);
}

/// First problem found, in field order; ConfigError::None for a usable Config.
[[nodiscard]] inline ConfigError validate(const Config& c) noexcept {
  if (c.cycle_time_us == 0U) {
    return ConfigError::CycleTimeZero;
  }
  if (c.discrepancy_cycles > kMaxTimerCycles) {
    return ConfigError::DiscrepancyTooLarge;
  }
  if (c.arming_timeout_cycles > kMaxTimerCycles) {
    return ConfigError::ArmingTimeoutTooLarge;
  }
  if (c.max_stop_cycles > kMaxTimerCycles) {
    return ConfigError::MaxStopTooLarge;
  }
  if (c.t2_confirm_timeout_cycles == 0U || c.t2_confirm_timeout_cycles > kMaxTimerCycles) {
    return ConfigError::T2ConfirmTimeoutOutOfRange;
  }
  if (c.t1_speed_limit_mm_s <= 0) {
    return ConfigError::T1LimitNotPositive;
  }
  if (c.t1_speed_limit_mm_s > kIsoReducedSpeedMmS) {
    return ConfigError::T1LimitAboveReducedSpeed;
  }
  // T2 is the high-speed manual mode: its limit lies above T1's and within the arm's reach.
  if (c.t2_speed_limit_mm_s <= c.t1_speed_limit_mm_s || c.t2_speed_limit_mm_s > kMaxT2SpeedLimitMmS) {
    return ConfigError::T2LimitOutOfRange;
  }
  if (!std::isfinite(c.zero_velocity_rad_s) || c.zero_velocity_rad_s < 0.0) {
    return ConfigError::ZeroVelocityInvalid;
  }
  // ZERO and OVER_T1 must not overlap: a speed the standstill class admits is below T1's.
  if (!std::isfinite(c.standstill_speed_window_mm_s) || c.standstill_speed_window_mm_s <= 0.0 ||
      c.standstill_speed_window_mm_s >= static_cast<double>(c.t1_speed_limit_mm_s)) {
    return ConfigError::StandstillWindowOutOfRange;
  }
  if (c.command_queue_limit == 0U || c.command_queue_limit > kMaxQueueCapacity) {
    return ConfigError::QueueLimitOutOfRange;
  }
  if (c.fieldbus_expected_working_counter == 0U) {
    return ConfigError::FieldbusWorkingCounterZero;
  }
  if (c.fieldbus_lost_cycles_limit > kMaxFieldbusLostCycles) {
    return ConfigError::FieldbusToleranceTooLarge;
  }
  if (c.feedback_allowed_cycles > kMaxFeedbackCycles) {
    return ConfigError::FeedbackTimeTooLarge;
  }
  if (!c.tool_offset_m.has_value()) {
    return ConfigError::ToolOffsetNotGiven;
  }
  for (const double v : *c.tool_offset_m) {
    if (!std::isfinite(v)) {
      return ConfigError::DhTableNotFinite;
    }
  }
  for (const DhRow& row : c.dh) {
    if (!std::isfinite(row.a_m) || !std::isfinite(row.alpha_rad) || !std::isfinite(row.d_m) ||
        !std::isfinite(row.theta_offset_rad)) {
      return ConfigError::DhTableNotFinite;
    }
  }
  // Checked last: it needs a finite arm and tool. Every joint at the threshold must stay
  // inside the standstill window at the tool (else C25 and C10 see a moving arm as ZERO).
  if (!(zero_class_tcp_bound_mm_s(c.dh, *c.tool_offset_m, c.zero_velocity_rad_s) <= c.standstill_speed_window_mm_s)) {
    return ConfigError::ZeroVelocityAboveWindow;
  }
  return ConfigError::None;
}

}  // namespace safestate
