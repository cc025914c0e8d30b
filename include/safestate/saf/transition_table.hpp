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
  HardwareFault,  // the cycle's hardware_fault input
  PairedAndSafe,  // estop != NONE, not danger, a good health summary received
  Danger,         // estop = SET or timed out or health bad
  EstopTimedOut,
  ClearSafeAndTold,  // estop = CLEAR, not danger, good health received, control HELD or REFUSED
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
    {"M01", bit(SafState::Emergency), StateGuard::ClearSafeAndTold, StateEffect::LeaveEmergency, "D"},
    {"M02", bit(SafState::Emergency), StateGuard::True, StateEffect::Stay, "-"},
}};

enum class ControlGuard : std::uint8_t {
  True,
  Granted,       // Confirm Control(accepted) answering our pending request (REQUESTED), or Report Control(us)
  EventRefused,  // Confirm Control(refused); the row's mask makes it an answer to a pending request
  EventUs,
  EventOther,
  AgeReportDataTimeout,  // control_age >= ReportDataTimeoutCycles
  AgeMessageInterval,    // control_age >= MessageIntervalCycles
  EventUsNoRelease,      // ev = US and no release sent yet this cycle
};

enum class ControlEffect : std::uint8_t { Request, RequestAlarm, Grant, Refuse, Refresh, Tick, ReleaseAgain };

struct ControlRow {
  std::string_view id;
  Mask states;  // the (new) states the row applies in
  Mask control;
  ControlGuard guard;
  ControlEffect effect;
};

inline constexpr Mask kWaiting = static_cast<Mask>(bit(ControlStatus::Requested) | bit(ControlStatus::Refused));
inline constexpr Mask kAnyControl = 0x0F;
inline constexpr Mask kRaising = static_cast<Mask>(kAnyState & ~bit(SafState::Operational));
inline constexpr Mask kOperational = bit(SafState::Operational);

/// Design §7, first match wins: K01-K09 in PAIRING, EMERGENCY and FAULT; K10 in OPERATIONAL.
// clang-format off
inline constexpr std::array<ControlRow, 10> kControlRows{{
    {"K01", kRaising, bit(ControlStatus::Released), ControlGuard::True, ControlEffect::Request},
    {"K02", kRaising, kWaiting, ControlGuard::Granted, ControlEffect::Grant},
    {"K03", kRaising, bit(ControlStatus::Requested), ControlGuard::EventRefused, ControlEffect::Refuse},
    {"K04", kRaising, bit(ControlStatus::Requested), ControlGuard::AgeReportDataTimeout, ControlEffect::Request},
    {"K05", kRaising, bit(ControlStatus::Refused), ControlGuard::AgeMessageInterval, ControlEffect::Request},
    {"K06", kRaising, bit(ControlStatus::Held), ControlGuard::EventOther, ControlEffect::RequestAlarm},
    {"K07", kRaising, bit(ControlStatus::Held), ControlGuard::EventUs, ControlEffect::Refresh},
    {"K08", kRaising, bit(ControlStatus::Held), ControlGuard::AgeReportDataTimeout, ControlEffect::Request},
    {"K09", kRaising, kAnyControl, ControlGuard::True, ControlEffect::Tick},
    {"K10", kOperational, bit(ControlStatus::Released), ControlGuard::EventUsNoRelease, ControlEffect::ReleaseAgain},
}};
// clang-format on

}  // namespace safestate::saf
