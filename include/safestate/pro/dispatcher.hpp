// evt_dispatcher (PRO-05, docs/design/protection.md §8): one dispatch cycle per tick
// delivers the tick to the READY AOs in kDispatchOrder, each run to completion before the
// next, restricted to the critical AOs in Degraded and while shutting down. The model's
// `dispatched` is the sequence this returns. No heap: the result is a fixed array.
#pragma once

#include <array>
#include <cstddef>

#include "safestate/pro/ao_id.hpp"
#include "safestate/pro/dispatch_mode.hpp"

namespace safestate::pro {

struct DispatchRecord {
  std::array<AoId, kDispatchOrder.size()> order{};
  std::size_t count{0};
};

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

}  // namespace safestate::pro
