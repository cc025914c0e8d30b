// SPDX-License-Identifier: Apache-2.0
// The operator panel's plant simulator switches (design §11): what the simulated cell's
// devices are set to. One 32-bit word, so the bridge hands it to the control thread with
// one atomic store and the cycle reads it with one atomic load.
#pragma once

#include <cstdint>

#include "safestate/enable_position.hpp"
#include "safestate/selector_reading.hpp"

namespace safestate::link {

struct PlantSwitches {
  bool estop_pressed{false};       ///< the E-stop button: opens both channels
  bool estop_b_stuck_open{false};  ///< channel B stuck open (a wiring fault): B reads a demand
  bool gate_open{false};           ///< the safety gate: opens both channels
  EnablePosition enabling{EnablePosition::Released};
  SelectorReading selector{SelectorReading::Auto};
  bool drive_fault{false};

  [[nodiscard]] constexpr std::uint32_t pack() const noexcept {
    return static_cast<std::uint32_t>(estop_pressed) | static_cast<std::uint32_t>(estop_b_stuck_open) << 1U |
           static_cast<std::uint32_t>(gate_open) << 2U | static_cast<std::uint32_t>(drive_fault) << 3U |
           static_cast<std::uint32_t>(enabling) << 4U | static_cast<std::uint32_t>(selector) << 8U;
  }
  [[nodiscard]] static constexpr PlantSwitches unpack(std::uint32_t w) noexcept {
    PlantSwitches s;
    s.estop_pressed = (w & 1U) != 0;
    s.estop_b_stuck_open = (w >> 1U & 1U) != 0;
    s.gate_open = (w >> 2U & 1U) != 0;
    s.drive_fault = (w >> 3U & 1U) != 0;
    s.enabling = static_cast<EnablePosition>(w >> 4U & 0xFU);
    s.selector = static_cast<SelectorReading>(w >> 8U & 0xFU);
    return s;
  }
};

}  // namespace safestate::link
