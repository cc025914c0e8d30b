// SPDX-License-Identifier: Apache-2.0
// What a transition-table guard reads and an action changes.
#pragma once

#include "safestate/command.hpp"
#include "safestate/config.hpp"
#include "safestate/derived_inputs.hpp"
#include "safestate/machine_state.hpp"
#include "safestate/reset_interlock.hpp"
#include "safestate/state_id.hpp"

namespace safestate {

/// Guards read it (const); actions replace or update `state`. Everything else the manager
/// owns (stop_category, command_result, last_reject_reason) is set by the table engine
/// from the row's columns, not by actions, so the table alone shows it.
struct StepContext {
  MachineState& state;
  const DerivedInputs& in;
  const Config& config;
  bool config_valid;
  Command command;              ///< the popped command (§6 rows only)
  ResetInterlock& reset;        ///< K36/K37 memory; C07 and K05 update it
  std::size_t queued_commands;  ///< queue length before this cycle's pop (C07)
  StateId cycle_start_state;    ///< the state before §5 (K38)
};

}  // namespace safestate
