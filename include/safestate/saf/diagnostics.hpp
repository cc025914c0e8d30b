// SPDX-License-Identifier: Apache-2.0
// Counters of the service: messages accepted, rejected per reason (SAF-03).
#pragma once

#include <array>
#include <cstdint>

#include "safestate/saf/decode_error.hpp"
#include "safestate/saf/service_values.hpp"
#include "safestate/saf/wire_values.hpp"

namespace safestate::saf {

struct Diagnostics {
  std::uint64_t cycles = 0;
  std::uint64_t accepted = 0;
  std::array<std::uint64_t, kDecodeErrorCount> rejected{};  // indexed by DecodeError
  std::uint64_t inbound_dropped = 0;                        // datagrams beyond kMaxInboundPerCycle (transport)
  std::uint64_t rejected_source = 0;      // well-formed, but not from the peer of its kind (design §5)
  std::uint64_t rejected_stale = 0;       // from the right peer, outside the replay window
  std::uint64_t unsolicited_confirm = 0;  // a Confirm Control while no Request Control was pending
  std::uint64_t inconsistent_report = 0;  // a Report Control naming us with another authority
  std::uint64_t alarms = 0;               // times the authority contest was lost (K03, K06)
  bool subsystem_state_known = false;
  SubsystemState subsystem_state = SubsystemState::Initialize;  // last Report Subsystem State
  std::uint64_t last_set_emergency_cycle = 0;

  [[nodiscard]] std::uint64_t rejected_total() const noexcept {
    std::uint64_t n = 0;
    for (std::uint64_t r : rejected) n += r;
    return n + rejected_source + rejected_stale;
  }
};

}  // namespace safestate::saf
