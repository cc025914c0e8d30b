// evt_dispatcher (PRO-05, docs/design/protection.md §8): one dispatch cycle per tick
// delivers the tick to the READY AOs in kDispatchOrder, each run to completion before the
// next, restricted to the critical AOs in Degraded and while shutting down. The model's
// `dispatched` is the sequence this returns. No heap: the result is a fixed array.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "safestate/pro/ao_id.hpp"
#include "safestate/pro/dispatch_mode.hpp"
#include "safestate/pro/unit_status.hpp"

namespace safestate::pro {

struct DispatchRecord {
  std::array<AoId, kDispatchOrder.size()> order{};
  std::size_t count{0};
};

// The dispatcher is a unit too: while it is not READY (not started, failed, stopped) no
// dispatch cycle runs, whatever the supervisor's state allows (§8; the model's
// Dispatchable). ProtectionRuntime and the conformance double both go through this.
[[nodiscard]] constexpr DispatchMode dispatch_gate(DispatchMode mode, UnitStatus dispatcher) noexcept {
  return dispatcher == UnitStatus::ready ? mode : DispatchMode::none;
}

// What ao_safety evaluated in a dispatch cycle (§8, the model's safety_input): not
// dispatched, the snapshot monitoring took earlier in the same cycle, or the snapshot
// mailbox the runtime empties at the start of every cycle (an invalid sensor to ao_safety).
enum class SafetyInput : std::uint8_t { none = 0, fresh, empty };

// `ready(ao)` says whether the AO reported READY; `run(ao)` runs its dispatch to completion.
template <typename Ready, typename Run>
[[nodiscard]] DispatchRecord dispatch_cycle(DispatchMode mode, Ready&& ready, Run&& run) {
  DispatchRecord record;
  if (mode == DispatchMode::none) return record;
  for (const AoId ao : kDispatchOrder) {
    if (!ready(ao)) continue;
    if (mode == DispatchMode::critical_only && !is_critical(ao)) continue;
    run(ao);
    record.order[record.count++] = ao;
  }
  return record;
}

[[nodiscard]] constexpr SafetyInput safety_input_of(const DispatchRecord& r) noexcept {
  bool monitoring = false;
  for (std::size_t i = 0; i < r.count; ++i) {
    if (r.order[i] == AoId::monitoring) monitoring = true;
    if (r.order[i] == AoId::safety) return monitoring ? SafetyInput::fresh : SafetyInput::empty;
  }
  return SafetyInput::none;
}

}  // namespace safestate::pro
