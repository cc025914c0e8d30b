// The seven units reporting to the supervisor (readiness gates, §6), in the model's
// order of names (RuntimeSupervisor.tla `Units`).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "safestate/pro/ao_id.hpp"

namespace safestate::pro {

enum class UnitId : std::uint8_t { timer = 0, dispatcher, monitoring, control, safety, diagnostics, comms };

inline constexpr std::size_t kUnitCount = 7;

[[nodiscard]] constexpr std::size_t index(UnitId u) noexcept { return static_cast<std::size_t>(u); }

// The unit of an active object (the AOs are five of the seven units).
[[nodiscard]] constexpr UnitId unit_of(AoId ao) noexcept {
  return static_cast<UnitId>(static_cast<std::uint8_t>(ao) + 2);
}

}  // namespace safestate::pro
