#include "safestate/pro/fan_speed_controller.hpp"

#include <algorithm>

namespace safestate::pro {

std::uint8_t FanSpeedController::step(std::int16_t temperature_c) noexcept {
  const std::int32_t error = static_cast<std::int32_t>(temperature_c) - tuning_.setpoint_c;
  const std::int32_t lo = tuning_.min_percent;
  const std::int32_t p = tuning_.kp_percent_per_c * error;
  const std::int32_t unclamped = p + integral_milli_ / 1000;
  // Anti-windup: integrate only when that does not push further into saturation.
  const bool saturated_high = unclamped >= 100 && error > 0;
  const bool saturated_low = unclamped <= lo && error < 0;
  if (!saturated_high && !saturated_low) {
    integral_milli_ = std::clamp(integral_milli_ + tuning_.ki_milli_percent_per_c_tick * error, 0, 100'000);
  }
  command_ = static_cast<std::uint8_t>(std::clamp(p + integral_milli_ / 1000, lo, std::int32_t{100}));
  return command_;
}

}  // namespace safestate::pro
