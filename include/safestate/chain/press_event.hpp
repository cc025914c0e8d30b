// The press models' input events (docs/design/hydraulic-press.md §7) as one scan's
// PressInputs: the one mapping shared by the Python binding and the accident replay test.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "safestate/chain/press_inputs.hpp"

namespace safestate::chain {

/// One model input event ("motor_on", "start", "mode2", ...) as one scan's inputs;
/// `continuous` is the held continuous-running level, updated by continuous_on/_off.
/// std::nullopt for a name that is not a model event (then `continuous` is unchanged).
[[nodiscard]] inline std::optional<PressInputs> press_inputs_of(std::string_view e, bool& continuous) noexcept {
  constexpr std::string_view known[] = {"motor_on",      "motor_off",      "start",     "ret",
                                        "step_done",     "mode1",          "mode2",     "mode3",
                                        "continuous_on", "continuous_off", "temp_high", "temp_ok"};
  bool ok = false;
  for (const std::string_view k : known) ok = ok || e == k;
  if (!ok) return std::nullopt;
  if (e == "continuous_on") continuous = true;
  if (e == "continuous_off") continuous = false;
  PressInputs i;
  i.continuous = continuous;
  i.motor_on = e == "motor_on";
  i.motor_off = e == "motor_off";
  i.start = e == "start";
  i.ret = e == "ret";
  i.step_done = e == "step_done";
  i.temp_high = e == "temp_high";
  i.temp_ok = e == "temp_ok";
  if (e.substr(0, 4) == "mode") i.mode = static_cast<std::uint8_t>(e.back() - '0');
  return i;
}

}  // namespace safestate::chain
