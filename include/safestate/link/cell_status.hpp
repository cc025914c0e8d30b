// SPDX-License-Identifier: Apache-2.0
// The snapshot the control cycle publishes every cycle through the seqlock (design §11):
// everything the operator panel shows. Trivially copyable, fixed size.
#pragma once

#include <array>
#include <cstdint>

#include "safestate/scan_outputs.hpp"
#include "safestate/status_record.hpp"

namespace safestate::link {

struct CellStatus {
  std::uint64_t cycle{0};  ///< cycles run since start
  StatusRecord status{};
  ScanOutputs outputs{};
  std::int16_t cycle_row{-1};            ///< index into kTransitionTable of the §5 row, -1 before the first cycle
  std::int16_t command_row{-1};          ///< the §6 row, -1 when no command was popped
  std::int16_t last_transition_row{-1};  ///< the row of the most recent state change (sticky, for the diagram)
  StateId last_transition_from{StateId::Boot};  ///< the state that row left
  /// The last state changes, oldest first (a ring: `recent[(recent_next + i) % 8]`), so that a
  /// reader polling every 50 ms still sees a state that lasted a few cycles.
  struct Transition {
    std::uint64_t cycle{0};
    std::int16_t row{-1};
    StateId from{StateId::Boot};
    StateId to{StateId::Boot};
  };
  std::array<Transition, 8> recent{};
  std::uint8_t recent_next{0};
  std::uint32_t plant_switches{0};  ///< PlantSwitches::pack() the cycle read
  bool operator_link_ok{false};     ///< what the cycle read (HeartbeatMonitor::sample)
  std::uint32_t heartbeat_age_cycles{0};
  std::uint64_t commands_popped{0};  ///< commands the cycle popped so far (their results are queued in order)
};

/// One popped command's result, numbered in pop order (= submit order of queued commands).
struct CommandOutcome {
  std::uint64_t seq{0};
  CommandResult result{};
};

}  // namespace safestate::link
