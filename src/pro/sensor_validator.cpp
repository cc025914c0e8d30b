#include "safestate/pro/sensor_validator.hpp"

#include <cstdlib>

namespace safestate::pro {

SensorVerdict SensorValidator::validate(const RawSample& s) noexcept {
  SensorVerdict v = SensorVerdict::ok;
  const bool frozen = has_previous_ && s.sequence == previous_.sequence;
  frozen_ticks_ = frozen ? static_cast<std::uint8_t>(frozen_ticks_ < 255 ? frozen_ticks_ + 1 : 255) : 0;
  if (s.fault_flag) {
    v = SensorVerdict::flagged;
  } else if (s.temperature_c < range_.temp_min_c || s.temperature_c > range_.temp_max_c ||
             s.voltage_dv > range_.volt_max_dv) {
    v = SensorVerdict::out_of_range;
  } else if (has_previous_ && (std::abs(s.temperature_c - previous_.temperature_c) > range_.temp_slew_c ||
                               std::abs(static_cast<int>(s.voltage_dv) - static_cast<int>(previous_.voltage_dv)) >
                                   range_.volt_slew_dv)) {
    v = SensorVerdict::implausible_slew;
  } else if (frozen_ticks_ >= range_.stuck_ticks) {
    v = SensorVerdict::stuck;
  }
  previous_ = s;
  has_previous_ = true;
  last_ = v;
  return v;
}

SensorSnapshot SensorValidator::snapshot(const RawSample& s) noexcept {
  const bool ok = validate(s) == SensorVerdict::ok;
  return SensorSnapshot{s.temperature_c, s.voltage_dv, ok, false};
}

}  // namespace safestate::pro
