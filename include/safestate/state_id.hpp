// SPDX-License-Identifier: Apache-2.0
// The observable leaf states of the SystemStateManager (design §4, RSM-01).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// Leaf states. OPERATIONAL is the superstate of AutoIdle, AutoRunning, ManualIdle and
/// ManualJogging; it is never itself the observable state.
enum class StateId : std::uint8_t {
  Boot,
  ErrorLockout,
  EstopActive,
  EstopResetNeeded,
  Idle,
  Arming,
  AutoIdle,
  AutoRunning,
  ManualIdle,
  ManualJogging,
  Stopping,
  Hold,
};

inline constexpr std::size_t kStateCount = 12;

inline constexpr std::array<StateId, kStateCount> kAllStates{
    StateId::Boot,       StateId::ErrorLockout,  StateId::EstopActive, StateId::EstopResetNeeded,
    StateId::Idle,       StateId::Arming,        StateId::AutoIdle,    StateId::AutoRunning,
    StateId::ManualIdle, StateId::ManualJogging, StateId::Stopping,    StateId::Hold,
};

[[nodiscard]] constexpr std::string_view to_string(StateId s) noexcept {
  switch (s) {
    case StateId::Boot: return "BOOT";
    case StateId::ErrorLockout: return "ERROR_LOCKOUT";
    case StateId::EstopActive: return "ESTOP_ACTIVE";
    case StateId::EstopResetNeeded: return "ESTOP_RESET_NEEDED";
    case StateId::Idle: return "IDLE";
    case StateId::Arming: return "ARMING";
    case StateId::AutoIdle: return "AUTO_IDLE";
    case StateId::AutoRunning: return "AUTO_RUNNING";
    case StateId::ManualIdle: return "MANUAL_IDLE";
    case StateId::ManualJogging: return "MANUAL_JOGGING";
    case StateId::Stopping: return "STOPPING";
    case StateId::Hold: return "HOLD";
  }
  return "?";
}

/// Powered states (§4): contactor closed, drives enabled, brakes released (§7, INV-POWER).
[[nodiscard]] constexpr bool is_powered(StateId s) noexcept {
  switch (s) {
    case StateId::Arming:
    case StateId::AutoIdle:
    case StateId::AutoRunning:
    case StateId::ManualIdle:
    case StateId::ManualJogging:
    case StateId::Stopping:
    case StateId::Hold: return true;
    default: return false;
  }
}

/// Motion states (§4): the robot may move on command.
[[nodiscard]] constexpr bool is_motion(StateId s) noexcept {
  return s == StateId::AutoRunning || s == StateId::ManualJogging;
}

/// Sub-states of the OPERATIONAL superstate.
[[nodiscard]] constexpr bool is_operational(StateId s) noexcept {
  return s == StateId::AutoIdle || s == StateId::AutoRunning || s == StateId::ManualIdle || s == StateId::ManualJogging;
}

}  // namespace safestate
