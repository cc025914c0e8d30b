// ao_control's regulation (§4): a PI controller of the fan command on temperature, in
// integer arithmetic. Output 0 ... 100 %, never below the minimum airflow; the integral
// is held while the output saturates in the direction of the error (anti-windup).
#pragma once

#include <cstdint>

namespace safestate::pro {

struct FanTuning {
  std::int16_t setpoint_c{55};
  std::int32_t kp_percent_per_c{5};
  std::int32_t ki_milli_percent_per_c_tick{200};  // 0.2 % per °C and tick = 2 %/°C/s
  std::uint8_t min_percent{20};
};

class FanSpeedController {
 public:
  explicit FanSpeedController(FanTuning tuning = {}) noexcept : tuning_(tuning) {}

  // One control step on a valid temperature; returns the command in percent.
  [[nodiscard]] std::uint8_t step(std::int16_t temperature_c) noexcept;
  [[nodiscard]] std::uint8_t command() const noexcept { return command_; }
  [[nodiscard]] std::int32_t integral_milli_percent() const noexcept { return integral_milli_; }

 private:
  FanTuning tuning_;
  std::int32_t integral_milli_{0};
  std::uint8_t command_{100};  // full cooling until the first valid reading
};

}  // namespace safestate::pro
