// SPDX-License-Identifier: Apache-2.0
// A simulated robot cell around the SystemStateManager (for the demo and the operator
// panel; never part of the control cycle's product code): operator devices as switches,
// drives that report ready a few cycles after power-on, and a very simple robot that
// speeds up in motion states and ramps down (or is braked) otherwise.
#pragma once

#include <cstddef>
#include <cstdint>

#include "safestate/config.hpp"
#include "safestate/enable_position.hpp"
#include "safestate/jog_setpoint.hpp"
#include "safestate/scan_inputs.hpp"
#include "safestate/scan_outputs.hpp"
#include "safestate/selector_reading.hpp"
#include "safestate/sim/bus_master.hpp"
#include "safestate/state_id.hpp"

namespace safestate::sim {

/// The simulated demo cell's parameters: the design-page defaults, no tool on the flange.
[[nodiscard]] inline Config demo_cell_config() noexcept {
  Config c;
  c.tool_offset_m = kFlangeTcp;
  return c;
}

class CellPlant {
 public:
  CellPlant() noexcept {
    in_.estop_closed = {true, true};
    in_.safeguard_closed = {true, true};
    in_.enabling = {EnablePosition::Released, EnablePosition::Released};
    select(SelectorReading::Auto);
    in_.self_test_ok = true;
    in_.operator_link_ok = true;
    in_.q = {0.0, -1.2, 1.1, -1.4, -1.57, 0.0};
  }

  [[nodiscard]] ScanInputs& inputs() noexcept { return in_; }
  /// The drives' and the bus's levels; the control loop turns them into the process image
  /// (bus_image) with the manager's watchdog.
  [[nodiscard]] BusLevels& bus_levels() noexcept { return levels_; }
  [[nodiscard]] const ScanInputs& inputs() const noexcept { return in_; }

  void select(SelectorReading mode) noexcept {
    in_.selector.auto_ = mode == SelectorReading::Auto;
    in_.selector.t1 = mode == SelectorReading::T1;
    in_.selector.t2 = mode == SelectorReading::T2;
  }
  void enabling(EnablePosition p) noexcept { in_.enabling = {p, p}; }

  /// Advance the plant by one cycle given the controller's last outputs.
  void react(const ScanOutputs& out, StateId state, const JogSetpoint& jog) noexcept {
    // The contactor's auxiliary contact and the brakes' feedback follow their command (C30).
    in_.contactor_feedback_closed = out.contactor_closed;
    in_.brake_feedback_released = out.brake_release;
    // Drives become ready 3 cycles after power-on.
    powered_cycles_ = out.contactor_closed ? powered_cycles_ + 1 : 0;
    levels_.servo_ready = powered_cycles_ >= 3;
    // Robot speed: ramps toward 1 in motion, toward 0 otherwise; brakes stop it at once.
    const bool moving = state == StateId::AutoRunning || state == StateId::ManualJogging;
    if (!out.brake_release) {
      speed_ = 0;
    } else if (moving && speed_ < 10) {
      ++speed_;
    } else if (!moving && speed_ > 0) {
      --speed_;
    }
    in_.qd = {};
    const double rate = 0.01 * speed_;  // rad/s, well under the T1 limit at this pose
    if (state == StateId::ManualJogging && jog.axis >= 1 && jog.axis <= 6) {
      in_.qd[static_cast<std::size_t>(jog.axis - 1)] = rate * jog.direction;
    } else if (speed_ > 0) {
      in_.qd = {rate, -rate, rate, 0.0, 0.0, 0.0};
    }
  }

 private:
  ScanInputs in_{};
  BusLevels levels_{true, false, false};
  int powered_cycles_{0};
  int speed_{0};
};

}  // namespace safestate::sim
