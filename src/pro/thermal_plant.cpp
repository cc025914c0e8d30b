#include "safestate/pro/thermal_plant.hpp"

#include <cmath>

namespace safestate::pro {

ControllerInputs ThermalPlant::inputs() const noexcept {
  ControllerInputs in;
  in.sample.temperature_c = static_cast<std::int16_t>(std::lround(temperature_c_));
  in.sample.voltage_dv = supply_dv_;
  in.sample.sequence = sequence_;
  in.driver_fault = driver_fault();
  return in;
}

void ThermalPlant::step(std::uint8_t fan_command_percent, bool load_enable) noexcept {
  fan_percent_ = driver_fault() ? 0.0 : static_cast<double>(fan_command_percent);
  load_on_ = load_enable;
  const double heat = load_enable ? heat_w_ : 0.0;
  const double g = p_.g_still_w_per_k + p_.g_fan_w_per_k * fan_percent_ / 100.0;
  temperature_c_ += p_.tick_s * (heat - g * (temperature_c_ - p_.ambient_c)) / p_.heat_capacity_j_per_k;
  if (!stuck_) ++sequence_;
}

}  // namespace safestate::pro
