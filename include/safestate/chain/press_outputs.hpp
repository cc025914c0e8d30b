#pragma once
// The energised outputs of the hydraulic press, one bit per Output, and the analog setpoints.
#include <cstdint>

#include "safestate/chain/press_output.hpp"
#include "safestate/chain/press_step.hpp"

namespace safestate::chain {

struct PressOutputs {
  std::uint16_t bits = 0;
  // The analog outputs of the mode parameters (design page §3), 0 when not driven.
  std::uint16_t pressure_bar = 0;  // press pressure setpoint, while the press valve is on
  std::uint16_t speed_mm_s = 0;    // ram speed setpoint, while the fast-advance valve is on
  [[nodiscard]] constexpr bool on(Output o) const noexcept { return (bits >> static_cast<int>(o)) & 1U; }
  constexpr void set(Output o, bool v) noexcept {
    const auto mask = static_cast<std::uint16_t>(1U << static_cast<int>(o));
    bits = v ? static_cast<std::uint16_t>(bits | mask) : static_cast<std::uint16_t>(bits & ~mask);
  }
  // Any of the eight stroke valves (INV-PRESS).
  [[nodiscard]] constexpr bool any_stroke_output() const noexcept {
    for (int k = 1; k < stroke_steps; ++k) {
      if (on(valve_of_step(k))) return true;
    }
    return false;
  }
};

}  // namespace safestate::chain
