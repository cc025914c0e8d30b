// SPDX-License-Identifier: Apache-2.0
// A seeded random but plausible plant and operator for long runs of the manager: safety
// inputs whose two channels follow a common demand with a short random lag (and now and
// then a stuck channel), a mode selector that is sometimes turned, drives that become ready
// or fault, a robot that moves or stands, and an operator who sends random commands.
// Allocation-free, so the heap test can use it inside its counted region.
#pragma once

#include <cstdint>
#include <random>

#include "safestate/command.hpp"
#include "safestate/scan_inputs.hpp"
#include "ssm_test_support.hpp"

namespace ssm_test {

class RandomPlant {
 public:
  explicit RandomPlant(std::uint32_t seed) : rng_(seed) {
    in_ = healthy(SelectorReading::Auto);
    in_.self_test_ok = chance(0.97);
  }

  /// The inputs of the next cycle. `at_rest_commanded`: the last outputs command no motion
  /// (power off, or every axis Disabled/StandStill): the robot then stays at rest but for
  /// a rare creep (a fault that the standstill monitor, C25, must catch).
  /// `bus`: the manager's watchdog, from which the simulated master numbers its frames.
  /// `last`: the outputs the manager wrote last, which the contactor's and the brakes'
  /// feedback follow but for a rare episode of 1..6 cycles stuck at the other level (a slow
  /// or welded contact: within feedback_allowed_cycles C30 tolerates it, beyond it locks out).
  const ScanInputs& next(const FieldbusWatchdog& bus, bool at_rest_commanded, const ScanOutputs& last) {
    if (contactor_stuck_ == 0 && chance(0.0005)) contactor_stuck_ = 1 + uniform(6);
    if (brake_stuck_ == 0 && chance(0.0005)) brake_stuck_ = 1 + uniform(6);
    in_.contactor_feedback_closed = contactor_stuck_ > 0 ? !last.contactor_closed : last.contactor_closed;
    in_.brake_feedback_released = brake_stuck_ > 0 ? !last.brake_release : last.brake_release;
    if (contactor_stuck_ > 0) --contactor_stuck_;
    if (brake_stuck_ > 0) --brake_stuck_;
    follow(estop_demand_, in_.estop_closed, 0.004, 0.03);
    follow(gate_demand_, in_.safeguard_closed, 0.01, 0.03);
    // Enabling device: the operator moves it; the two channels follow with a lag.
    if (chance(0.02)) enable_target_ = pick_enable();
    for (EnablePosition* ch : {&in_.enabling.a, &in_.enabling.b}) {
      if (*ch != enable_target_ && chance(0.5)) *ch = enable_target_;
    }
    if (chance(0.0004)) in_.enabling.b = pick_enable();  // a glitch
    // Mode selector: turned now and then; a turn passes through "no contact" briefly.
    if (chance(0.004)) {
      mode_target_ = static_cast<SelectorReading>(1 + uniform(3));
      in_.selector = contacts(SelectorReading::Invalid);
    } else if (in_.selector.reading() != mode_target_ && chance(0.4)) {
      in_.selector = contacts(mode_target_);
    }
    if (chance(0.0005)) in_.selector = SelectorContacts{true, true, false};  // welded contact
    // Drives become ready a few cycles after power-up and stay ready, but for a rare loss
    // (C27 must catch it with the brakes released).
    if (levels_.servo_ready ? chance(0.0005) : chance(0.05)) levels_.servo_ready = !levels_.servo_ready;
    if (levels_.drive_fault ? chance(0.1) : chance(0.002)) levels_.drive_fault = !levels_.drive_fault;
    levels_.fieldbus_ok = !chance(0.0003);  // a lost EtherCAT frame / missed cycle deadline (C24)
    in_.bus = sim::bus_image(bus, levels_);
    in_.operator_link_ok = !chance(0.001);  // the operator client's heartbeat expired (C26)
    if (at_rest_commanded) {
      in_.qd = chance(0.002) ? kSlow : kRest;
    } else if (chance(0.05)) {
      const std::uint32_t u = uniform(20);
      in_.qd = u < 10 ? kRest : (u < 18 ? kSlow : kFast);
    }
    return in_;
  }

  /// A random operator command, submitted in about a third of the cycles.
  bool next_command(Command& c) {
    if (!chance(0.3)) return false;
    const auto kind = static_cast<CommandKind>(uniform(kCommandKindCount));
    c = Command{kind, 0, 0, 0};
    if (kind == CommandKind::JogStart) {
      c.axis = chance(0.9) ? static_cast<std::int32_t>(1 + uniform(6)) : static_cast<std::int32_t>(uniform(9)) - 1;
      c.direction = chance(0.9) ? (chance(0.5) ? 1 : -1) : 0;
      c.speed_mm_s =
          chance(0.95) ? static_cast<std::int32_t>(1 + uniform(600)) : -static_cast<std::int32_t>(uniform(3));
    }
    return true;
  }

  [[nodiscard]] const ScanInputs& inputs() const { return in_; }
  [[nodiscard]] const sim::BusLevels& levels() const { return levels_; }

  /// What next() needs from the last outputs: no motion commanded.
  [[nodiscard]] static bool at_rest(const ScanOutputs& out) {
    for (const AxisState a : out.axes) {
      if (a != AxisState::Disabled && a != AxisState::StandStill && a != AxisState::ErrorStop) return false;
    }
    return !out.ramp_down_request && out.commanded_speed_mm_s == 0;
  }

 private:
  bool chance(double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < p; }
  std::uint32_t uniform(std::uint32_t n) { return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(rng_); }
  EnablePosition pick_enable() {
    const std::uint32_t u = uniform(10);
    return u < 7 ? EnablePosition::Middle : (u < 9 ? EnablePosition::Released : EnablePosition::Panic);
  }

  // A dual-channel contact: the demand toggles with p_toggle; each channel follows it with
  // probability p_follow per cycle (a lag of a few cycles), except a stuck channel.
  void follow(bool& demand_closed, ChannelPair<bool>& ch, double p_toggle, double p_stick) {
    if (chance(p_toggle)) {
      demand_closed = !demand_closed;
      stuck_ = chance(p_stick) ? static_cast<int>(uniform(2)) : -1;
    }
    if (ch.a != demand_closed && stuck_ != 0 && chance(0.5)) ch.a = demand_closed;
    if (ch.b != demand_closed && stuck_ != 1 && chance(0.5)) ch.b = demand_closed;
    if (stuck_ >= 0 && chance(0.01)) stuck_ = -1;  // the stuck contact frees itself
  }

  std::mt19937 rng_;
  sim::BusLevels levels_{};
  ScanInputs in_{};
  std::uint32_t contactor_stuck_{0};  // cycles the contactor feedback still disagrees
  std::uint32_t brake_stuck_{0};      // likewise the brake feedback
  bool estop_demand_{true};
  bool gate_demand_{true};
  int stuck_{-1};
  EnablePosition enable_target_{EnablePosition::Middle};
  SelectorReading mode_target_{SelectorReading::Auto};
};

}  // namespace ssm_test
