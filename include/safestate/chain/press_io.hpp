#pragma once
// Inputs, outputs and observable state of the hydraulic press (docs/design/hydraulic-press.md
// §2, §3, §6), shared by the chain press and the flat defective reference.
#include <cstdint>

namespace safestate::chain {

// One scan's inputs. Buttons are edges (true in the scan they are pressed).
struct PressInputs {
  bool motor_on = false;   // MON
  bool motor_off = false;  // MOFF (wins over motor_on)
  bool start = false;      // Star (two buttons in series)
  bool ret = false;        // RET: back to Ready
  bool step_done = false;  // the limit switch / sensor completing the active stroke
  std::uint8_t mode = 0;   // mode selector edge: 1..3, 0 = no change
  bool continuous = false; // run-kind switch (level): continuous vs single-step
  bool temp_high = false;  // oil above the cooling limit
  bool temp_ok = false;    // oil back under it
};

enum class Output : std::uint8_t {
  motor, feed_valve, locate_valve, clamp_valve, fast_valve, press_valve,
  blow_valve, eject_valve, scrap_valve, lamp, cool_pump, count_,
};

// Stroke steps (Cur_Runing of the flat program); none = the sequence is not active.
enum class PressStep : std::uint8_t {
  ready, feed, locate, clamp, fast_advance, pressing, blow, eject, clear_scrap, none,
};
inline constexpr int stroke_steps = 9;

[[nodiscard]] constexpr const char* to_string(PressStep s) noexcept {
  constexpr const char* names[] = {"Ready", "Feed", "Locate", "Clamp", "FastAdvance",
                                   "Pressing", "Blow", "Eject", "ClearScrap", "none"};
  return names[static_cast<int>(s)];
}
[[nodiscard]] constexpr const char* to_string(Output o) noexcept {
  constexpr const char* names[] = {"motor", "feed_valve", "locate_valve", "clamp_valve",
                                   "fast_valve", "press_valve", "blow_valve", "eject_valve",
                                   "scrap_valve", "lamp", "cool_pump", "?"};
  return names[static_cast<int>(o)];
}
// The valve a stroke step energises (Ready: none; design page §3).
[[nodiscard]] constexpr bool step_has_valve(int step) noexcept { return step >= 1 && step < stroke_steps; }
[[nodiscard]] constexpr Output valve_of_step(int step) noexcept {
  return static_cast<Output>(static_cast<int>(Output::feed_valve) + step - 1);
}

struct PressOutputs {
  std::uint16_t bits = 0;
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

// The model's observables (design page §6): motor, mode (0 = none), step, outputs.
struct PressObservation {
  bool motor = false;
  int mode = 0;
  PressStep step = PressStep::none;
  PressOutputs outputs{};
};

}  // namespace safestate::chain
