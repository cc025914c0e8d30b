// What the supervisor reads at the start of a tick (§6, §7): every unit's reported status,
// the fault inputs, the operator's shutdown request, and control's report that the outputs
// are safe (shutdown step 1).
#pragma once

#include <array>

#include "safestate/pro/unit_id.hpp"
#include "safestate/pro/unit_status.hpp"

namespace safestate::pro {

struct SupervisorInputs {
  std::array<UnitStatus, kUnitCount> status{};  // indexed by UnitId
  bool fatal_fault{false};
  bool watchdog_ok{true};
  bool shutdown_requested{false};
  bool outputs_safe_reported{false};
};

}  // namespace safestate::pro
