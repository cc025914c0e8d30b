// SPDX-License-Identifier: Apache-2.0
// The search's per-successor path, inline where it runs: exec (actions.cpp) hands every
// successor to on_emit (one worker) or offer (a worker of several), which look it up in
// the seen-set and store it; search.cpp and workers.cpp use the same lookups.  Out of
// line, their calls cost the small specs several per cent of their instructions.
#pragma once

#include <algorithm>

#include "engine.hpp"

namespace safestate::tla_native {

// Index of the state, or -1 after adding it to the seen-set (then the caller stores it).
inline int64_t Engine::find_or_insert(const uint32_t* x) {
  uint64_t h = key_hash(x);
  int64_t found = find(x, h);
  if (found < 0) insert(h, uint32_t(nstates()));
  return found;
}

// The seen-set's index of a state (or view), -1 if it has none (read-only).
inline int64_t Engine::find(const uint32_t* x, uint64_t h) const {
  const SeenShard& sh = seen[shard_of(h)];
  if (sh.table.empty()) return -1;
  size_t mask = sh.table.size() - 1;
  size_t pos = h & mask;
  while (sh.table[pos] != kUnset) {
    if (std::equal(x, x + key_len(), key_of(sh.table[pos]))) return sh.table[pos];
    pos = (pos + 1) & mask;
  }
  return -1;
}

// Adds a state known to be new (its key's hash h) to its shard.
inline void Engine::insert(uint64_t h, uint32_t idx) {
  SeenShard& sh = seen[shard_of(h)];
  if ((sh.count + 1) * 2 > sh.table.size()) {
    std::vector<uint32_t> old(std::max<size_t>(sh.table.size() * 2, 256), kUnset);
    old.swap(sh.table);
    size_t mask = sh.table.size() - 1;
    for (uint32_t id : old) {
      if (id == kUnset) continue;
      size_t pos = key_hash(key_of(id)) & mask;
      while (sh.table[pos] != kUnset) pos = (pos + 1) & mask;
      sh.table[pos] = id;
    }
  }
  size_t mask = sh.table.size() - 1, pos = h & mask;
  while (sh.table[pos] != kUnset) pos = (pos + 1) & mask;
  sh.table[pos] = idx;
  ++sh.count;
}

inline void Engine::add(const uint32_t* x, int32_t par, int32_t lf, int lvl) {
  arena.insert(arena.end(), x, x + nvars);
  if (view) view_keys.push_back(view_key);
  parent.push_back(par);
  leaf.push_back(lf);
  if (lvl > max_level()) level_start.push_back(uint32_t(nstates() - 1));
  if (nstates() % 20000 == 0) periodic();
}

inline bool Engine::holds_all(const std::vector<Node*>& preds, Ctx& c, int* which) {
  for (size_t i = 0; i < preds.size(); ++i)
    if (!boolean(preds[i], c, "predicate")) {
      if (which) *which = int(i);
      return false;
    }
  return true;
}

// A successor (emit_kind 1) or initial state (0) of the one-worker search: inside the
// model (constraints), new (the seen-set), then its invariants.
inline void Engine::on_emit(Ctx& c, int lf) {
  ++generated;
  for (int i = 0; i < nvars; ++i)
    if (c.t[i] == kUnset) fail("successor state is not completely specified", 0);
  Ctx sc{c.t, nullptr, nullptr};
  bool in_model = holds_all(constraints, sc, nullptr);
  if (in_model && !action_constraints.empty() && emit_kind == 1) {
    Ctx ac{c.s, c.t, nullptr};
    in_model = holds_all(action_constraints, ac, nullptr);
  }
  bool is_new = true;
  int64_t idx = -1;
  if (in_model) {
    if (view) view_key = eval(view, sc);
    int64_t found = find_or_insert(view ? &view_key : c.t);
    if (found < 0) {
      idx = int64_t(nstates());
      add(c.t, emit_kind ? int32_t(head) : -1, emit_kind ? lf : -1, emit_kind ? cur_level + 1 : 1);
    } else {
      is_new = false;
    }
    if (record_edges && emit_kind == 1) record_edge(uint32_t(head), uint32_t(found < 0 ? idx : found), lf);
    if (!label_vars.empty())
      record_label(emit_kind ? uint32_t(head) : 0xFFFFFFFFu, uint32_t(found < 0 ? idx : found), c.t);
  }
  if (!is_new) return;
  int which = -1;
  if (!holds_all(invariants, sc, &which)) {
    result = "safety failure";
    violated = which;
    initial_violation = emit_kind == 0;
    if (idx >= 0) {
      trace_to = idx;
    } else {
      trace_to = emit_kind ? int64_t(head) : -1;
      extra.assign(c.t, c.t + nvars);
      extra_leaf = lf;
    }
    throw Stop{};
  }
}

// A successor found by a worker: new unless seen (in an earlier level, or earlier in
// this one by the one worker's order); a new state's invariants are checked.
inline void Engine::offer(Ctx& c, int lf) {
  ++generated;
  uint64_t key = (uint64_t(parent_) << 32) | rank_++;
  for (int i = 0; i < nvars; ++i)
    if (c.t[i] == kUnset) fail("successor state is not completely specified", 0);
  Ctx sc{c.t, nullptr, nullptr};
  bool in_model = holds_all(constraints, sc, nullptr);
  if (in_model && !action_constraints.empty()) {
    Ctx ac{c.s, c.t, nullptr};
    in_model = holds_all(action_constraints, ac, nullptr);
  }
  if (in_model) {
    uint32_t vk = view ? eval(view, sc) : 0;
    const uint32_t* x = view ? &vk : c.t;
    uint64_t h = master_->key_hash(x);
    if (master_->find(x, h) >= 0 || !keep(x, h, c.t, vk, key, lf)) return;
  }
  if (!holds_all(invariants, sc, nullptr)) throw Stop{};
}

// Stores the state in its shard of Fresh; false if the shard has it with a smaller key.
inline bool Engine::keep(const uint32_t* x, uint64_t h, const uint32_t* state, uint32_t vk, uint64_t key, int lf) {
  Fresh::Shard& sh = fresh_->shards[shard_of(h)];
  std::lock_guard<std::mutex> lock(sh.mu);
  size_t mask = sh.table.size() - 1, pos = h & mask;
  int kl = key_len();
  auto key_at = [&](uint32_t i) { return view ? &sh.view_keys[i] : &sh.states[size_t(i) * size_t(nvars)]; };
  while (sh.table[pos] != kUnset) {
    uint32_t i = sh.table[pos];
    if (std::equal(x, x + kl, key_at(i))) {
      if (sh.keys[i] < key) return false;
      sh.keys[i] = key;
      sh.leaves[i] = lf;
      std::copy(state, state + nvars, sh.states.begin() + ptrdiff_t(i) * nvars);
      return true;
    }
    pos = (pos + 1) & mask;
  }
  uint32_t i = uint32_t(sh.keys.size());
  sh.table[pos] = i;
  sh.keys.push_back(key);
  sh.leaves.push_back(lf);
  sh.states.insert(sh.states.end(), state, state + nvars);
  if (view) sh.view_keys.push_back(vk);
  if ((i + 1) * 2 > sh.table.size()) {
    sh.table.assign(sh.table.size() * 2, kUnset);
    mask = sh.table.size() - 1;
    for (uint32_t j = 0; j <= i; ++j) {
      const uint32_t* y = key_at(j);
      size_t q = master_->key_hash(y) & mask;
      while (sh.table[q] != kUnset) q = (q + 1) & mask;
      sh.table[q] = j;
    }
  }
  return true;
}

}  // namespace safestate::tla_native
