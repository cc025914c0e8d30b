// A unit's status as reported to the runtime supervisor (its readiness gate,
// docs/design/protection.md §6). The values are the model's (RuntimeSupervisor.tla).
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class UnitStatus : std::uint8_t { init = 0, ready, failed, stopped };

}  // namespace safestate::pro
