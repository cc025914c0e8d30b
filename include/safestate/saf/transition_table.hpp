// SPDX-License-Identifier: Apache-2.0
// The rows of design §6 (state rows, transitions A-E) and §7 (control rows) as data.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "safestate/saf/service_values.hpp"

namespace safestate::saf {

/// A set of states or control statuses as a bit mask (bit = enum value).
using Mask = std::uint8_t;
template <typename E>
[[nodiscard]] constexpr Mask bit(E e) noexcept {
  return static_cast<Mask>(1U << static_cast<unsigned>(e));
}
inline constexpr Mask kAnyState = 0x0F;

enum class StateGuard : std::uint8_t {
  True,
  HardwareFault,         // the cycle's hardware_fault input
  PairedAndSafe,         // estop != NONE and not danger
  Danger,                // estop = SET or timed out or health bad
  EstopTimedOut,
  ClearAndSafe,          // estop = CLEAR and not danger
};

enum class StateEffect : std::uint8_t { Stay, EnterFault, LeaveEmergency, EnterEmergency };

struct StateRow {
  std::string_view id;
  Mask source;
  StateGuard guard;
  StateEffect effect;
  std::string_view transition;  // the seed's letter, or "-"
};

/// Design §6, first match wins.
inline constexpr std::array<StateRow, 10> kStateRows{{
    {"F01", bit(SafState::Fault), StateGuard::True, StateEffect::Stay, "-"},
    {"E01", kAnyState, StateGuard::HardwareFault, StateEffect::EnterFault, "E"},
    {"P01", bit(SafState::Pairing), StateGuard::PairedAndSafe, StateEffect::LeaveEmergency, "A"},
    {"P02", bit(SafState::Pairing), StateGuard::Danger, StateEffect::EnterEmergency, "C"},
    {"P03", bit(SafState::Pairing), StateGuard::True, StateEffect::Stay, "-"},
    {"O01", bit(SafState::Operational), StateGuard::EstopTimedOut, StateEffect::EnterEmergency, "B"},
    {"O02", bit(SafState::Operational), StateGuard::Danger, StateEffect::EnterEmergency, "C"},
    {"O03", bit(SafState::Operational), StateGuard::True, StateEffect::Stay, "-"},
    {"M01", bit(SafState::Emergency), StateGuard::ClearAndSafe, StateEffect::LeaveEmergency, "D"},
    {"M02", bit(SafState::Emergency), StateGuard::True, StateEffect::Stay, "-"},
}};

enum class ControlGuard : std::uint8_t {
  True,
  EventAccepted,
  EventRefused,
  EventOther,
  AgeReportDataTimeout,  // control_age >= ReportDataTimeoutCycles
  AgeMessageInterval,    // control_age >= MessageIntervalCycles
};

enum class ControlEffect : std::uint8_t { Request, Grant, Refuse, Refresh, Tick };

struct ControlRow {
  std::string_view id;
  Mask control;
  ControlGuard guard;
  ControlEffect effect;
};

inline constexpr Mask kWaiting = static_cast<Mask>(bit(ControlStatus::Requested) | bit(ControlStatus::Refused));
inline constexpr Mask kAnyControl = 0x0F;

/// Design §7, first match wins; run only in PAIRING, EMERGENCY and FAULT.
inline constexpr std::array<ControlRow, 9> kControlRows{{
    {"K01", bit(ControlStatus::Released), ControlGuard::True, ControlEffect::Request},
    {"K02", kWaiting, ControlGuard::EventAccepted, ControlEffect::Grant},
    {"K03", bit(ControlStatus::Requested), ControlGuard::EventRefused, ControlEffect::Refuse},
    {"K04", bit(ControlStatus::Requested), ControlGuard::AgeReportDataTimeout, ControlEffect::Request},
    {"K05", bit(ControlStatus::Refused), ControlGuard::AgeMessageInterval, ControlEffect::Request},
    {"K06", bit(ControlStatus::Held), ControlGuard::EventOther, ControlEffect::Request},
    {"K07", bit(ControlStatus::Held), ControlGuard::EventAccepted, ControlEffect::Refresh},
    {"K08", bit(ControlStatus::Held), ControlGuard::AgeReportDataTimeout, ControlEffect::Request},
    {"K09", kAnyControl, ControlGuard::True, ControlEffect::Tick},
}};

}  // namespace safestate::saf
