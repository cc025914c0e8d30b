// SPDX-License-Identifier: Apache-2.0
// The enumerated field values of the wire format (design §10).
#pragma once

#include <cstdint>
#include <string_view>

namespace safestate::saf {

/// Report Health Summary: Error and Fatal raise EMERGENCY (C), Warning does not.
enum class Health : std::uint8_t { Normal = 0, Warning = 1, Error = 2, Fatal = 3 };
inline constexpr std::uint8_t kHealthMax = 3;

/// Confirm Control response code.
enum class ControlResponse : std::uint8_t {
  Accepted = 0,
  NotAvailable = 1,
  InsufficientAuthority = 2,
};
inline constexpr std::uint8_t kControlResponseMax = 2;

/// Report / Set Subsystem State.
enum class SubsystemState : std::uint8_t {
  Initialize = 0,
  Operational = 1,
  Emergency = 2,
  Failure = 3,
};
inline constexpr std::uint8_t kSubsystemStateMax = 3;

/// Request Control action (the seed's outgoing set has no Release Control message).
enum class ControlAction : std::uint8_t { Request = 0, Release = 1 };
inline constexpr std::uint8_t kControlActionMax = 1;

[[nodiscard]] constexpr std::string_view to_string(Health h) noexcept {
  switch (h) {
    case Health::Normal: return "NORMAL";
    case Health::Warning: return "WARNING";
    case Health::Error: return "ERROR";
    case Health::Fatal: return "FATAL";
  }
  return "?";
}

[[nodiscard]] constexpr std::string_view to_string(SubsystemState s) noexcept {
  switch (s) {
    case SubsystemState::Initialize: return "INITIALIZE";
    case SubsystemState::Operational: return "OPERATIONAL";
    case SubsystemState::Emergency: return "EMERGENCY";
    case SubsystemState::Failure: return "FAILURE";
  }
  return "?";
}

}  // namespace safestate::saf
