// SPDX-License-Identifier: Apache-2.0
// The values of the service's observable data (design §4), spelt as in the model.
#pragma once

#include <cstdint>
#include <string_view>

namespace safestate::saf {

/// SAF-01.
enum class SafState : std::uint8_t { Pairing, Operational, Emergency, Fault };
/// The last Set Estop received.
enum class EstopView : std::uint8_t { None, Clear, Set };
/// The last health summary received (None: none yet).
enum class HealthView : std::uint8_t { None, Normal, Warning, Error, Fatal };
/// Control of the Subsystem State service (§7).
enum class ControlStatus : std::uint8_t { Released, Requested, Refused, Held };
/// The Request Control sent in a cycle.
enum class OutRequest : std::uint8_t { None, Request, Release };
/// The Set Subsystem State sent in a cycle.
enum class OutSetState : std::uint8_t { None, Operational, Emergency };
/// The control-related message of a cycle (§5: the last one wins). Accepted / Refused: a
/// Confirm Control; Us: a Report Control naming us with our authority; Other: a Report
/// Control naming another holder or nobody.
enum class ControlEvent : std::uint8_t { None, Accepted, Refused, Us, Other };

[[nodiscard]] constexpr std::string_view to_string(SafState v) noexcept {
  switch (v) {
    case SafState::Pairing: return "PAIRING";
    case SafState::Operational: return "OPERATIONAL";
    case SafState::Emergency: return "EMERGENCY";
    case SafState::Fault: return "FAULT";
  }
  return "?";
}
[[nodiscard]] constexpr std::string_view to_string(EstopView v) noexcept {
  switch (v) {
    case EstopView::None: return "NONE";
    case EstopView::Clear: return "CLEAR";
    case EstopView::Set: return "SET";
  }
  return "?";
}
[[nodiscard]] constexpr std::string_view to_string(HealthView v) noexcept {
  switch (v) {
    case HealthView::None: return "NONE";
    case HealthView::Normal: return "NORMAL";
    case HealthView::Warning: return "WARNING";
    case HealthView::Error: return "ERROR";
    case HealthView::Fatal: return "FATAL";
  }
  return "?";
}
[[nodiscard]] constexpr std::string_view to_string(ControlStatus v) noexcept {
  switch (v) {
    case ControlStatus::Released: return "RELEASED";
    case ControlStatus::Requested: return "REQUESTED";
    case ControlStatus::Refused: return "REFUSED";
    case ControlStatus::Held: return "HELD";
  }
  return "?";
}
[[nodiscard]] constexpr std::string_view to_string(OutRequest v) noexcept {
  switch (v) {
    case OutRequest::None: return "NONE";
    case OutRequest::Request: return "REQUEST";
    case OutRequest::Release: return "RELEASE";
  }
  return "?";
}
[[nodiscard]] constexpr std::string_view to_string(OutSetState v) noexcept {
  switch (v) {
    case OutSetState::None: return "NONE";
    case OutSetState::Operational: return "OPERATIONAL";
    case OutSetState::Emergency: return "EMERGENCY";
  }
  return "?";
}

}  // namespace safestate::saf
