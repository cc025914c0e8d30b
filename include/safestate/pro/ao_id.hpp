// The active objects of the fan controller in their fixed dispatch order (PRO-05,
// docs/design/protection.md §8): the enumerator value is the rank.
#pragma once

#include <array>
#include <cstdint>

namespace safestate::pro {

enum class AoId : std::uint8_t { monitoring = 0, control, safety, diagnostics, comms };

inline constexpr std::array<AoId, 5> kDispatchOrder{AoId::monitoring, AoId::control, AoId::safety, AoId::diagnostics,
                                                    AoId::comms};

// Critical AOs keep running in Degraded and while shutting down (§8); comms does not.
[[nodiscard]] constexpr bool is_critical(AoId ao) noexcept { return ao != AoId::comms; }

}  // namespace safestate::pro
