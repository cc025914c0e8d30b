// What one supervisor tick decided (§7, §8): the row that fired, the lifecycle events it
// sends, and what the dispatcher may deliver afterwards.
#pragma once

#include <cstddef>

#include "safestate/pro/dispatch_mode.hpp"
#include "safestate/pro/supervisor_row.hpp"
#include "safestate/pro/supervisor_state.hpp"

namespace safestate::pro {

struct SupervisorStep {
  const SupervisorRow* row{nullptr};
  SupervisorState state{SupervisorState::init};
  DispatchMode mode{DispatchMode::none};
  bool entered_degraded{false};  // EVT_DEGRADED to control, safety, diagnostics
  bool recovered{false};         // EVT_RESET to the dispatcher, EVT_RECOVERY to the AOs
  bool stop_requested{false};    // a stop step was requested this tick (stop_target())
};

}  // namespace safestate::pro
