// A thermal/electrical plant for the fan controller (demo and closed-loop tests): a heat
// load warming a lumped thermal mass, a fan cooling it in proportion to its command, a
// supply voltage feeding the fan driver (which cuts out below its undervoltage lockout),
// and the sensor front end that samples temperature and voltage once per tick.
//   C dT/dt = P_load - (g0 + g1 * fan/100) (T - T_ambient)
// Not part of the controller; doubles are fine here.
#pragma once

#include <cstdint>

#include "safestate/pro/controller_inputs.hpp"

namespace safestate::pro {

struct PlantParameters {
  double heat_capacity_j_per_k{50.0};
  double ambient_c{25.0};
  double g_still_w_per_k{2.0};           // natural convection, fan stopped
  double g_fan_w_per_k{18.0};            // added at 100 % fan
  std::uint16_t driver_lockout_dv{170};  // fan driver undervoltage lockout: 17.0 V
  double tick_s{0.1};
};

class ThermalPlant {
 public:
  explicit ThermalPlant(PlantParameters p = {}, double start_c = 25.0) noexcept : p_(p), temperature_c_(start_c) {}

  void set_heat_load_w(double w) noexcept { heat_w_ = w; }
  void set_supply_dv(std::uint16_t dv) noexcept { supply_dv_ = dv; }
  // The air the fan draws in (a blocked inlet or a hot room raises it).
  void set_ambient_c(double c) noexcept { p_.ambient_c = c; }
  // The front end freezes (its frame counter stops): a stuck sensor.
  void set_sensor_stuck(bool stuck) noexcept { stuck_ = stuck; }

  // What the controller reads at the start of a tick.
  [[nodiscard]] ControllerInputs inputs() const noexcept;
  // Advances one tick with the fan command and the equipment permissive the controller
  // wrote: the heat load dissipates only while the permissive is on.
  void step(std::uint8_t fan_command_percent, bool load_enable) noexcept;
  [[nodiscard]] bool load_on() const noexcept { return load_on_; }

  [[nodiscard]] double temperature_c() const noexcept { return temperature_c_; }
  [[nodiscard]] std::uint16_t supply_dv() const noexcept { return supply_dv_; }
  [[nodiscard]] bool driver_fault() const noexcept { return supply_dv_ < p_.driver_lockout_dv; }
  // The fan's actual speed in percent (0 while the driver is locked out).
  [[nodiscard]] double fan_percent() const noexcept { return fan_percent_; }

 private:
  PlantParameters p_;
  double temperature_c_;
  double heat_w_{0.0};
  double fan_percent_{0.0};
  std::uint16_t supply_dv_{240};
  std::uint8_t sequence_{0};
  bool stuck_{false};
  bool load_on_{false};
};

}  // namespace safestate::pro
