// SPDX-License-Identifier: Apache-2.0
// The breadth-first search with one worker.  A state is an array of nvars ids in one
// arena that is also the queue (head: the next state to expand); the seen-set is
// open-addressing tables (shards by hash) of state indices over that arena (exact: the
// id arrays are compared on a hash hit).  With several workers, run() hands the levels
// to search_levels (workers.cpp) and takes over where a level must be searched again.
#include <algorithm>
#include <fstream>

#include "search_inl.hpp"

namespace safestate::tla_native {

size_t Engine::rss_mb() const {
  std::ifstream f("/proc/self/statm");
  size_t pages = 0, rss = 0;
  f >> pages >> rss;
  return rss * 4096 / (1024 * 1024);
}

// Ctrl-C, SIGTERM: the search runs without the GIL, so Python's handlers run only
// here; the exception they raise (KeyboardInterrupt, the CLI's Terminated) leaves
// run() as it is, with the counts so far readable.
void Engine::poll_signals() {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

void Engine::periodic() {
  poll_signals();
  if (max_memory_mb && rss_mb() > max_memory_mb) {
    result = "memory";
    throw Stop{};
  }
  auto now = std::chrono::steady_clock::now();
  if (!progress.is_none() && now - last_progress >= std::chrono::seconds(5)) {
    last_progress = now;
    py::gil_scoped_acquire gil;
    progress(max_level(), generated, nstates(), nstates() - head);
  }
}

void Engine::record_edge(uint32_t src, uint32_t dst, int lf) {
  buf_.clear();
  if (size_t(lf) < leaf_params.size())
    for (int64_t s : leaf_params[size_t(lf)]) buf_.push_back(slots[size_t(s)]);
  edge_src.push_back(src);
  edge_dst.push_back(dst);
  edge_leaf.push_back(uint32_t(lf));
  edge_params.push_back(st.mk_seq(buf_));
}

std::vector<uint64_t> Engine::copy_masks() const {
  size_t k = 0;  // the initial states' labels come first, without a source
  while (k < label_src.size() && label_src[k] == 0xFFFFFFFFU) ++k;
  if (edge_leaf.size() != label_src.size() - k || label_vars.empty() || label_vars.size() > 64) return {};
  uint32_t nleaves = 0;
  for (uint32_t lf : edge_leaf) nleaves = std::max(nleaves, lf + 1);
  const uint64_t all = label_vars.size() == 64 ? ~uint64_t(0) : (uint64_t(1) << label_vars.size()) - 1;
  std::vector<uint64_t> copied(nleaves, all);
  for (size_t j = 0; j < edge_leaf.size(); ++j) {
    uint64_t& c = copied[edge_leaf[j]];
    if (!c) continue;
    const uint32_t* label = st.items(label_val[k + j]);
    const uint32_t* source = arena.data() + size_t(label_src[k + j]) * size_t(nvars);
    for (uint64_t bits = c; bits; bits &= bits - 1) {
      const int q = __builtin_ctzll(bits);
      if (label[q] != source[size_t(label_vars[size_t(q)])]) c &= ~(uint64_t(1) << q);
    }
  }
  return copied;
}

void Engine::record_label(uint32_t src, uint32_t dst, const uint32_t* t) {
  buf_.clear();
  for (int64_t v : label_vars) buf_.push_back(t[size_t(v)]);
  label_src.push_back(src);
  label_dst.push_back(dst);
  label_val.push_back(st.mk_seq(buf_));
}

// Any evaluation error ends the search with the error's text and location: the Python
// engine then re-checks the model for TLC's exact report (the Python evaluator is the
// reference).
void Engine::run() {
  stk_.clear();
  std::vector<uint32_t> t(size_t(nvars), kUnset);
  try {
    try {
      emit_kind = 0;
      Ctx c{nullptr, t.data(), nullptr};
      exec(init, c);
      if (!progress.is_none()) {
        py::gil_scoped_acquire gil;
        progress(-1, generated, nstates(), 0);  // initial states done
      }
      initial_count = nstates();
      emit_kind = 1;
      if (workers > 1 && !record_edges && label_vars.empty()) search_levels();
      while (head < nstates()) {
        while (size_t(cur_level) < level_start.size() && head >= level_start[size_t(cur_level)]) ++cur_level;
        std::vector<uint32_t> cur(arena.begin() + ptrdiff_t(head * size_t(nvars)),
                                  arena.begin() + ptrdiff_t((head + 1) * size_t(nvars)));
        Ctx nc{cur.data(), t.data(), nullptr};
        before = generated;
        if ((head & 255) == 0) poll_signals();
        exec(next, nc);
        if (generated == before && check_deadlock) {
          result = "deadlock failure";
          trace_to = int64_t(head);
          throw Stop{};
        }
        ++head;
      }
    } catch (const EvalFailure& e) {
      result = "error";
      error = e.message;
      error_loc = e.loc;
      error_state = emit_kind ? int64_t(head) : -1;
    }
  } catch (const Stop&) {
  }
}

}  // namespace safestate::tla_native
