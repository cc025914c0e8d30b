// What the dispatcher may deliver in the supervisor's current state (§8).
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class DispatchMode : std::uint8_t {
  none,           // INIT, STOPPED: nothing is dispatched
  all,            // RUN: every READY AO
  critical_only,  // DEGRADED, SHUTTING_DOWN: only critical AOs
};

}  // namespace safestate::pro
