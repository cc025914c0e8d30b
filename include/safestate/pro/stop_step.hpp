// Controlled shutdown (§9): the steps in their order, one per tick, each done when its
// unit reports. Step 1 is not a unit's stop but control's report that the outputs are in
// their safe state; protection (safety) stops only at step 4, after it.
#pragma once

#include <array>

#include "safestate/pro/unit_id.hpp"

namespace safestate::pro {

struct StopStep {
  bool outputs;  // step 1: control drives the outputs safe (and keeps running)
  UnitId unit;   // the unit asked (control for step 1)
};

inline constexpr std::array<StopStep, 8> kStopOrder{{
    {true, UnitId::control},
    {false, UnitId::comms},
    {false, UnitId::diagnostics},
    {false, UnitId::safety},
    {false, UnitId::control},
    {false, UnitId::monitoring},
    {false, UnitId::dispatcher},
    {false, UnitId::timer},
}};

}  // namespace safestate::pro
