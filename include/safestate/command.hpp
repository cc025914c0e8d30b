// SPDX-License-Identifier: Apache-2.0
// One operator-interface command (design §6, RSM-13).
#pragma once

#include <cstdint>

#include "safestate/command_kind.hpp"

namespace safestate {

/// A command as submitted; trivially copyable so the SPSC queue copies it without heap.
/// The jog arguments are plain integers so that out-of-range values reach K26 and are
/// rejected there (INVALID_ARGUMENT) instead of being narrowed by the caller.
struct Command {
  CommandKind kind{CommandKind::Reset};
  std::int32_t axis{0};        ///< JOG_START: 1..6
  std::int32_t direction{0};   ///< JOG_START: -1 or +1
  std::int32_t speed_mm_s{0};  ///< JOG_START: > 0, clamped to the T1 limit in T1 (K29)

  [[nodiscard]] static constexpr Command reset() noexcept { return {CommandKind::Reset, 0, 0, 0}; }
  [[nodiscard]] static constexpr Command servo_on() noexcept { return {CommandKind::ServoOn, 0, 0, 0}; }
  [[nodiscard]] static constexpr Command servo_off() noexcept { return {CommandKind::ServoOff, 0, 0, 0}; }
  [[nodiscard]] static constexpr Command start() noexcept { return {CommandKind::Start, 0, 0, 0}; }
  [[nodiscard]] static constexpr Command pause() noexcept { return {CommandKind::Pause, 0, 0, 0}; }
  [[nodiscard]] static constexpr Command resume() noexcept { return {CommandKind::Resume, 0, 0, 0}; }
  [[nodiscard]] static constexpr Command jog_start(std::int32_t axis, std::int32_t direction,
                                                   std::int32_t speed_mm_s) noexcept {
    return {CommandKind::JogStart, axis, direction, speed_mm_s};
  }
  [[nodiscard]] static constexpr Command jog_stop() noexcept { return {CommandKind::JogStop, 0, 0, 0}; }
  [[nodiscard]] static constexpr Command t2_confirm() noexcept { return {CommandKind::T2Confirm, 0, 0, 0}; }
};

}  // namespace safestate
