// The signals an active object receives (docs/design/protection.md §1, §7-§9): the tick
// of the dispatch cycle, the supervisor's lifecycle events (always delivered, also to an
// AO that is not dispatched) and the interface events ao_safety posts to diagnostics.
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class AoSignal : std::uint8_t {
  tick = 0,          // the dispatch cycle's tick (only to dispatched AOs)
  start,             // init: acquire resources, report READY or FAILED
  degraded,          // EVT_DEGRADED (I02, I03, R01)
  recovery,          // EVT_RECOVERY (D01)
  stop_outputs,      // shutdown step 1, to control: drive the outputs to their safe state
  stop,              // EVT_STOP: stop and report STOPPED
  operating_status,  // IF_OperatingStatus(protection state, override) to diagnostics
  fault_event,       // IF_FaultEvent(cause, tick) to diagnostics
};

}  // namespace safestate::pro
