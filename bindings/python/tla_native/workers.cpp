// SPDX-License-Identifier: Apache-2.0
// The search with several workers, level by level: the workers expand the current
// level's states (parents handed out in chunks) into Fresh; at the barrier the new
// states are sorted by key and stored as the one worker would store them.  A level
// where a worker meets a violation, deadlock or evaluation error is searched again by
// the one-worker loop (run()), which stops where the one worker stops, with its counts
// and trace.
#include <algorithm>
#include <thread>

#include "search_inl.hpp"

namespace safestate::tla_native {

void Fresh::clear() {
  for (size_t i = 0; i < kShards; ++i) {
    Shard& sh = shards[i];
    sh.states.clear();
    sh.view_keys.clear();
    sh.keys.clear();
    sh.leaves.clear();
    sh.table.assign(64, kUnset);
  }
  stop = false;
}

Engine::Engine(Engine& m, int) : store(m.store), nvars(m.nvars), slots(m.slots) {
  init = m.init;
  next = m.next;
  invariants = m.invariants;
  constraints = m.constraints;
  action_constraints = m.action_constraints;
  check_deadlock = m.check_deadlock;
  view = m.view;
  emit_kind = 1;
  foralls_.resize(m.foralls_.size());
  master_ = &m;
}

void Engine::search_levels() {
  std::vector<std::unique_ptr<Engine>> team;
  for (int w = 0; w < workers; ++w) team.emplace_back(new Engine(*this, w));
  Fresh fresh;
  worker_cpu.assign(size_t(workers), 0.0);
  st.concurrent = true;
  while (head < nstates()) {
    while (size_t(cur_level) < level_start.size() && head >= level_start[size_t(cur_level)]) ++cur_level;
    fresh.clear();
    fresh.lo = head;
    fresh.hi = nstates();
    fresh.next_parent = head;
    std::vector<std::thread> threads;
    for (int w = 1; w < workers; ++w) threads.emplace_back(&Engine::work, team[size_t(w)].get(), &fresh);
    team[0]->work(&fresh);
    for (auto& th : threads) th.join();
    double slowest = 0;
    for (size_t w = 0; w < team.size(); ++w) {
      worker_cpu[w] += team[w]->level_cpu_;
      slowest = std::max(slowest, team[w]->level_cpu_);
    }
    critical_cpu += slowest;
    if (fresh.stop) break;  // run() searches this level again with one worker
    for (auto& w : team) {
      generated += w->generated;
      w->generated = 0;
    }
    store_level(fresh, team);
  }
  st.concurrent = false;
}

void Engine::work(Fresh* f) {
  constexpr size_t kChunk = 16;
  std::vector<uint32_t> t(size_t(nvars), kUnset);
  fresh_ = f;
  double cpu0 = thread_cpu_seconds();
  const Engine& m = *master_;
  try {
    try {
      while (!f->stop.load(std::memory_order_relaxed)) {
        size_t p0 = f->next_parent.fetch_add(kChunk);
        if (p0 >= f->hi) break;
        for (size_t p = p0; p < std::min(p0 + kChunk, f->hi); ++p) {
          Ctx nc{m.arena.data() + p * size_t(nvars), t.data(), nullptr};
          parent_ = p - f->lo;
          rank_ = 0;
          before = generated;
          exec(next, nc);
          if (generated == before && check_deadlock) throw Stop{};
        }
      }
    } catch (const EvalFailure&) {
      f->stop = true;
    }
  } catch (const Stop&) {
    f->stop = true;
  }
  fresh_ = nullptr;
  level_cpu_ = thread_cpu_seconds() - cpu0;
}

// The barrier: the level's new states, in the one worker's order, stored; then each
// worker adds those of its shards to the seen-set.
void Engine::store_level(Fresh& f, std::vector<std::unique_ptr<Engine>>& team) {
  // Sorted by key: bucketed by parent (counting sort), each parent's few by rank.
  size_t nparents = f.hi - f.lo, total = 0;
  std::vector<uint32_t> start(nparents + 1, 0);
  for (size_t s = 0; s < Fresh::kShards; ++s)
    for (uint64_t key : f.shards[s].keys) ++start[(key >> 32) + 1], ++total;
  for (size_t p = 0; p < nparents; ++p) start[p + 1] += start[p];
  std::vector<std::pair<uint64_t, uint64_t>> order(total);  // (key, shard << 32 | index)
  for (size_t s = 0; s < Fresh::kShards; ++s)
    for (size_t i = 0; i < f.shards[s].keys.size(); ++i) {
      uint64_t key = f.shards[s].keys[i];
      order[start[key >> 32]++] = {key, (uint64_t(s) << 32) | i};
    }
  for (size_t p = 0, b = 0; p < nparents; b = start[p++])
    if (start[p] - b > 1) std::sort(order.begin() + ptrdiff_t(b), order.begin() + start[p]);
  for (auto& o : order) {
    Fresh::Shard& sh = f.shards[o.second >> 32];
    size_t i = o.second & 0xFFFFFFFFu;
    const uint32_t* x = &sh.states[i * size_t(nvars)];
    if (view) view_key = sh.view_keys[i];
    sh.keys[i] = nstates();  // now the state's index
    add(x, int32_t(f.lo + (o.first >> 32)), sh.leaves[i], cur_level + 1);
  }
  head = f.hi;
  std::vector<double> cpu(team.size(), 0.0);
  auto index = [this, &f, &cpu](size_t w) {
    double cpu0 = thread_cpu_seconds();
    for (size_t s = w; s < Fresh::kShards; s += size_t(workers))
      for (uint64_t idx : f.shards[s].keys) insert(key_hash(key_of(uint32_t(idx))), uint32_t(idx));
    cpu[w] = thread_cpu_seconds() - cpu0;
  };
  std::vector<std::thread> threads;
  for (size_t w = 1; w < team.size(); ++w) threads.emplace_back(index, w);
  index(0);
  for (auto& th : threads) th.join();
  for (size_t w = 0; w < cpu.size(); ++w) worker_cpu[w] += cpu[w];
  critical_cpu += *std::max_element(cpu.begin(), cpu.end());
}

}  // namespace safestate::tla_native
