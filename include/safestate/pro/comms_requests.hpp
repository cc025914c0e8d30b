// What the communications unit hands to the runtime once per tick (§9): the operator's
// requests received since the last tick, each consumed exactly once.
#pragma once

namespace safestate::pro {

struct CommsRequests {
  // A client wrote 1 to coil 0: request to clear the protection latch.
  bool latch_clear_request{false};
};

}  // namespace safestate::pro
