#pragma once
// The stroke steps of the hydraulic press (docs/design/hydraulic-press.md §3): Cur_Runing
// of the flat program.
#include <cstdint>

namespace safestate::chain {

// none = the sequence is not active (the motor is off).
enum class PressStep : std::uint8_t {
  ready,
  feed,
  locate,
  clamp,
  fast_advance,
  pressing,
  blow,
  eject,
  clear_scrap,
  none,
};
inline constexpr int stroke_steps = 9;

[[nodiscard]] constexpr const char* to_string(PressStep s) noexcept {
  constexpr const char* names[] = {"Ready",    "Feed", "Locate", "Clamp",      "FastAdvance",
                                   "Pressing", "Blow", "Eject",  "ClearScrap", "none"};
  return names[static_cast<int>(s)];
}

}  // namespace safestate::chain
