// The guards of the supervisor rows (docs/design/protection.md §6, §7).
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class SupervisorGuard : std::uint8_t {
  shutdown_requested,  // the operator asked for a controlled shutdown
  recovery_ok,         // every unit READY, no fatal fault, watchdog fine
  fault,               // some unit FAILED, a fatal fault, or the watchdog bad
  init_timeout,        // init_ticks + 1 >= InitTimeoutTicks
  all_stopped,         // every unit reported STOPPED
  always,
};

}  // namespace safestate::pro
