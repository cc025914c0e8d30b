#pragma once
// One row of a state-chain table (docs/design/state-chain.md §1): the document's STA.
#include <cstdint>

#include "safestate/chain/request_result.hpp"

namespace safestate::chain {

using StateIndex = std::uint8_t;
inline constexpr StateIndex no_state = 0xFF;

// What a state function may do to the chain: request a transition (run functions).
class Requests {
 public:
  using Fn = RequestResult (*)(void* chain, StateIndex src, StateIndex dst) noexcept;
  constexpr Requests(void* chain, Fn fn) noexcept : chain_(chain), fn_(fn) {}
  [[nodiscard]] RequestResult request(StateIndex src, StateIndex dst) const noexcept { return fn_(chain_, src, dst); }

 private:
  void* chain_;
  Fn fn_;
};

template <class Ctx>
using StateFn = void (*)(Ctx& ctx, const Requests& chain) noexcept;

template <class Ctx>
struct StateDef {
  const char* name;
  StateIndex parent;   // no_state for the root (document: ps)
  StateIndex initial;  // initial child of a sequential state, else no_state (px)
  bool parallel;       // every child starts a sub-chain (z)
  StateFn<Ctx> entry;  // fpin
  StateFn<Ctx> exit;   // fpdel
  StateFn<Ctx> run;    // fpRun: may request transitions
  StateFn<Ctx> work;   // fpDo: periodic work, never requests
};

}  // namespace safestate::chain
