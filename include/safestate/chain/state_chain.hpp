#pragma once
// The state-chain engine (docs/design/state-chain.md, SCH-01..04). Header-only, no heap,
// no exceptions. The table lists the states in pre-order (a parent before its children,
// each subtree contiguous), so entry is ascending table order over the entered subtree,
// exit and run are descending table order (leaf first, nested sub-chains before the
// state that started them). Validate the table with check_table() before use.
#include <array>
#include <cstddef>

#include "safestate/chain/call_log.hpp"
#include "safestate/chain/request_result.hpp"
#include "safestate/chain/state_def.hpp"
#include "safestate/chain/table_error.hpp"

namespace safestate::chain {

template <class Ctx, std::size_t N>
using StateTable = std::array<StateDef<Ctx>, N>;

template <class Ctx, std::size_t N>
[[nodiscard]] constexpr bool is_descendant(const StateTable<Ctx, N>& t, std::size_t d, std::size_t a) noexcept {
  for (StateIndex p = t[d].parent; p != no_state; p = t[p].parent) {
    if (p == a) return true;
  }
  return false;
}

// One past the last index of s's subtree (pre-order: the subtree is contiguous).
template <class Ctx, std::size_t N>
[[nodiscard]] constexpr std::size_t subtree_end(const StateTable<Ctx, N>& t, std::size_t s) noexcept {
  std::size_t j = s + 1;
  while (j < N && is_descendant(t, j, s)) ++j;
  return j;
}

template <class Ctx, std::size_t N>
[[nodiscard]] constexpr TableCheck check_table(const StateTable<Ctx, N>& t) noexcept {
  static_assert(N > 0 && N < no_state, "a chain has 1..254 states");
  if (t[0].parent != no_state) return {TableError::root_not_first, 0};
  for (std::size_t s = 1; s < N; ++s) {
    if (t[s].parent == no_state) return {TableError::second_root, static_cast<unsigned>(s)};
    if (t[s].parent >= s) return {TableError::parent_not_before, static_cast<unsigned>(s)};
  }
  for (std::size_t s = 0; s < N; ++s) {
    const std::size_t end = subtree_end(t, s);
    for (std::size_t j = end; j < N; ++j) {
      if (is_descendant(t, j, s)) return {TableError::subtree_not_contiguous, static_cast<unsigned>(j)};
    }
    const bool leaf = end == s + 1;
    if (t[s].parallel) {
      if (t[s].initial != no_state) return {TableError::parallel_with_initial, static_cast<unsigned>(s)};
      if (leaf) return {TableError::parallel_without_children, static_cast<unsigned>(s)};
    } else if (leaf) {
      if (t[s].initial != no_state) return {TableError::leaf_with_initial, static_cast<unsigned>(s)};
    } else if (t[s].initial >= N || t[t[s].initial].parent != s) {
      return {TableError::bad_initial, static_cast<unsigned>(s)};
    }
  }
  return {};
}

template <class Ctx, std::size_t N>
class StateChain {
 public:
  // The table must outlive the chain and pass check_table().
  constexpr StateChain(const StateTable<Ctx, N>& table, Ctx& ctx) noexcept : table_(table), ctx_(ctx) {}

  // Power-up (SCH-01): activate the root down to its initial leaves.
  void start() noexcept {
    log_.clear();
    if (!active_[0]) enter(0);
  }

  // SCH-02: a transition between siblings (src == dst: exit and re-enter).
  [[nodiscard]] RequestResult request(StateIndex src, StateIndex dst) noexcept {
    if (src >= N || dst >= N) return RequestResult::unknown_state;
    if (!active_[src]) return RequestResult::source_inactive;
    if (table_[src].parent != table_[dst].parent) return RequestResult::cross_level;
    if (active_[dst] && dst != src) return RequestResult::target_active;
    exit(src);
    enter(dst);
    return RequestResult::ok;
  }

  // SCH-04: the run functions of the active states, leaf to root per sub-chain. A state
  // exited by a request earlier in the same walk is skipped.
  void run() noexcept {
    log_.clear();
    walk(&StateDef<Ctx>::run);
  }
  // The do functions, same order (document: ST_Do).
  void work() noexcept { walk(&StateDef<Ctx>::work); }

  [[nodiscard]] bool is_active(StateIndex s) const noexcept { return s < N && active_[s]; }
  [[nodiscard]] const StateTable<Ctx, N>& table() const noexcept { return table_; }
  [[nodiscard]] static constexpr std::size_t size() noexcept { return N; }
  // The entry/exit calls of the last start() or run() (every request it made), in order.
  [[nodiscard]] const CallLog<2 * N>& calls() const noexcept { return log_; }

 private:
  static RequestResult request_thunk(void* self, StateIndex src, StateIndex dst) noexcept {
    return static_cast<StateChain*>(self)->request(src, dst);
  }
  [[nodiscard]] Requests requests() noexcept { return Requests{this, &request_thunk}; }

  // §2: s, then (ascending pre-order) every state whose parent was just entered and which
  // is a sub-chain root of a parallel parent or the parent's initial child.
  void enter(std::size_t s) noexcept {
    const std::size_t end = subtree_end(table_, s);
    for (std::size_t j = s; j < end; ++j) {
      if (j != s) {
        const StateDef<Ctx>& parent = table_[table_[j].parent];
        if (!active_[table_[j].parent] || !(parent.parallel || parent.initial == j)) continue;
      }
      active_[j] = true;
      log_.push(CallKind::entry, static_cast<StateIndex>(j));
      if (table_[j].entry != nullptr) table_[j].entry(ctx_, requests());
    }
  }

  // §3: the active states of s's subtree in descending pre-order (leaf first).
  void exit(std::size_t s) noexcept {
    for (std::size_t j = subtree_end(table_, s); j-- > s;) {
      if (!active_[j]) continue;
      log_.push(CallKind::exit, static_cast<StateIndex>(j));
      if (table_[j].exit != nullptr) table_[j].exit(ctx_, requests());
      active_[j] = false;
    }
  }

  void walk(StateFn<Ctx> StateDef<Ctx>::*fn) noexcept {
    const std::array<bool, N> snapshot = active_;
    for (std::size_t j = N; j-- > 0;) {
      if (snapshot[j] && active_[j] && table_[j].*fn != nullptr) (table_[j].*fn)(ctx_, requests());
    }
  }

  const StateTable<Ctx, N>& table_;
  Ctx& ctx_;
  std::array<bool, N> active_{};
  CallLog<2 * N> log_{};
};

}  // namespace safestate::chain
