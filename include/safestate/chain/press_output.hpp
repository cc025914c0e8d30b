#pragma once
// One output of the hydraulic press (docs/design/hydraulic-press.md §3, §4) and the valve
// each stroke step energises.
#include <cstdint>

#include "safestate/chain/press_step.hpp"

namespace safestate::chain {

enum class Output : std::uint8_t {
  motor,
  feed_valve,
  locate_valve,
  clamp_valve,
  fast_valve,
  press_valve,
  blow_valve,
  eject_valve,
  scrap_valve,
  lamp,
  cool_pump,
  count_,
};

[[nodiscard]] constexpr const char* to_string(Output o) noexcept {
  constexpr const char* names[] = {"motor",       "feed_valve",  "locate_valve", "clamp_valve",
                                   "fast_valve",  "press_valve", "blow_valve",   "eject_valve",
                                   "scrap_valve", "lamp",        "cool_pump",    "?"};
  return names[static_cast<int>(o)];
}
// The valve a stroke step energises (Ready: none; design page §3).
[[nodiscard]] constexpr bool step_has_valve(int step) noexcept { return step >= 1 && step < stroke_steps; }
[[nodiscard]] constexpr Output valve_of_step(int step) noexcept {
  return static_cast<Output>(static_cast<int>(Output::feed_valve) + step - 1);
}

}  // namespace safestate::chain
