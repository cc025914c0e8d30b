// SPDX-License-Identifier: Apache-2.0
// The states of the CiA 402 drive state machine (IEC 61800-7-201, "power drive system
// state machine"), as decoded from a drive's status word (design §2 "Drive status words").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

/// One drive's state. `Invalid` is a status word that matches no state of the standard's
/// table: an implausible reading, which the manager treats as a drive fault.
enum class Cia402State : std::uint8_t {
  NotReadyToSwitchOn,
  SwitchOnDisabled,
  ReadyToSwitchOn,
  SwitchedOn,
  OperationEnabled,
  QuickStopActive,
  FaultReactionActive,
  Fault,
  Invalid,
};

inline constexpr std::size_t kCia402StateCount = 9;

inline constexpr std::array<Cia402State, kCia402StateCount> kAllCia402States{
    Cia402State::NotReadyToSwitchOn,
    Cia402State::SwitchOnDisabled,
    Cia402State::ReadyToSwitchOn,
    Cia402State::SwitchedOn,
    Cia402State::OperationEnabled,
    Cia402State::QuickStopActive,
    Cia402State::FaultReactionActive,
    Cia402State::Fault,
    Cia402State::Invalid,
};

/// The upper-case name used by the design page and the binding.
[[nodiscard]] constexpr std::string_view to_string(Cia402State v) noexcept {
  switch (v) {
    case Cia402State::NotReadyToSwitchOn: return "NOT_READY_TO_SWITCH_ON";
    case Cia402State::SwitchOnDisabled: return "SWITCH_ON_DISABLED";
    case Cia402State::ReadyToSwitchOn: return "READY_TO_SWITCH_ON";
    case Cia402State::SwitchedOn: return "SWITCHED_ON";
    case Cia402State::OperationEnabled: return "OPERATION_ENABLED";
    case Cia402State::QuickStopActive: return "QUICK_STOP_ACTIVE";
    case Cia402State::FaultReactionActive: return "FAULT_REACTION_ACTIVE";
    case Cia402State::Fault: return "FAULT";
    case Cia402State::Invalid: return "INVALID";
  }
  return "?";
}

}  // namespace safestate
