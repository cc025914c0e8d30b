// SPDX-License-Identifier: Apache-2.0
// Operator commands (design §6).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// Operator-interface commands (§6, RSM-13).
enum class CommandKind : std::uint8_t {
  Reset,
  ServoOn,
  ServoOff,
  Start,
  Pause,
  Resume,
  JogStart,
  JogStop,
  T2Confirm,
};

inline constexpr std::size_t kCommandKindCount = 9;

inline constexpr std::array<CommandKind, kCommandKindCount> kAllCommandKinds{
    CommandKind::Reset,  CommandKind::ServoOn,  CommandKind::ServoOff, CommandKind::Start,     CommandKind::Pause,
    CommandKind::Resume, CommandKind::JogStart, CommandKind::JogStop,  CommandKind::T2Confirm,
};

/// The upper-case name used by the design page, the model and the conformance suite.
[[nodiscard]] constexpr std::string_view to_string(CommandKind v) noexcept {
  switch (v) {
    case CommandKind::Reset: return "RESET";
    case CommandKind::ServoOn: return "SERVO_ON";
    case CommandKind::ServoOff: return "SERVO_OFF";
    case CommandKind::Start: return "START";
    case CommandKind::Pause: return "PAUSE";
    case CommandKind::Resume: return "RESUME";
    case CommandKind::JogStart: return "JOG_START";
    case CommandKind::JogStop: return "JOG_STOP";
    case CommandKind::T2Confirm: return "T2_CONFIRM";
  }
  return "?";
}

}  // namespace safestate
