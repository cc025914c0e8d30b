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
  bool subsystem_state_known = false;
  SubsystemState subsystem_state = SubsystemState::Initialize;  // last Report Subsystem State
  std::uint64_t last_set_emergency_cycle = 0;

  [[nodiscard]] std::uint64_t rejected_total() const noexcept {
    std::uint64_t n = 0;
    for (std::uint64_t r : rejected) n += r;
    return n;
  }
};

}  // namespace safestate::saf
