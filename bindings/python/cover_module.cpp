// safestate._cover: the trace cover of conformance (python/safestate/conform/cover.py),
// the greedy walk that takes every edge of a model's state graph.  It is the same
// algorithm step for step as the description in cover.py (its docstring is the
// specification); it is in C++ because the walk's detours visit tens of millions of
// edges on the larger graphs (the Safety service: 342,240 edges, ~25 s in Python).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

using Ids = std::vector<int64_t>;

// Out-edges of every node, in edge id order (compressed rows).
struct OutEdges {
  std::vector<int64_t> first;  // n + 1 offsets into edges
  std::vector<int64_t> edges;
  OutEdges(int64_t n, const Ids& src) : first(size_t(n) + 1, 0), edges(src.size()) {
    for (int64_t s : src) ++first[size_t(s) + 1];
    for (size_t u = 0; u < size_t(n); ++u) first[u + 1] += first[u];
    std::vector<int64_t> fill(first.begin(), first.end() - 1);
    for (size_t e = 0; e < src.size(); ++e) edges[size_t(fill[size_t(src[e])]++)] = int64_t(e);
  }
  int64_t begin(int64_t u) const { return first[size_t(u)]; }
  int64_t end(int64_t u) const { return first[size_t(u) + 1]; }
};

// Strongly connected component of each node (iterative Tarjan).  Only equality of
// component ids is used, so any correct labelling gives the same walk.
std::vector<int64_t> components(int64_t n, const OutEdges& out, const Ids& dst) {
  std::vector<int64_t> index(size_t(n), -1), low(size_t(n), 0), comp(size_t(n), -1);
  std::vector<char> on_stack(size_t(n), 0);
  std::vector<int64_t> stack;
  std::vector<std::pair<int64_t, int64_t>> work;  // (node, position in its out-edges)
  int64_t counter = 0, ncomp = 0;
  for (int64_t root = 0; root < n; ++root) {
    if (index[size_t(root)] != -1) continue;
    work.emplace_back(root, out.begin(root));
    index[size_t(root)] = low[size_t(root)] = counter++;
    stack.push_back(root);
    on_stack[size_t(root)] = 1;
    while (!work.empty()) {
      auto& [u, i] = work.back();
      bool descended = false;
      while (i < out.end(u)) {
        int64_t v = dst[size_t(out.edges[size_t(i++)])];
        if (index[size_t(v)] == -1) {
          index[size_t(v)] = low[size_t(v)] = counter++;
          stack.push_back(v);
          on_stack[size_t(v)] = 1;
          work.emplace_back(v, out.begin(v));
          descended = true;
          break;
        }
        if (on_stack[size_t(v)]) low[size_t(u)] = std::min(low[size_t(u)], index[size_t(v)]);
      }
      if (descended) continue;
      int64_t done = u;
      if (low[size_t(done)] == index[size_t(done)]) {
        while (true) {
          int64_t v = stack.back();
          stack.pop_back();
          on_stack[size_t(v)] = 0;
          comp[size_t(v)] = ncomp;
          if (v == done) break;
        }
        ++ncomp;
      }
      work.pop_back();
      if (!work.empty()) {
        int64_t p = work.back().first;
        low[size_t(p)] = std::min(low[size_t(p)], low[size_t(done)]);
      }
    }
  }
  return comp;
}

// The untaken edges: a flag per edge and a count per node (cover.py's _Walker).
class Walker {
 public:
  Walker(int64_t n, const Ids& src, const Ids& dst)
      : src_(src),
        dst_(dst),
        out_(n, src),
        taken_(src.size(), 0),
        left_(size_t(n)),
        pos_(size_t(n)),
        comp_(components(n, out_, dst)),
        stamp_(size_t(n), 0),
        prev_(size_t(n), -1) {
    for (int64_t u = 0; u < n; ++u) {
      left_[size_t(u)] = out_.end(u) - out_.begin(u);
      pos_[size_t(u)] = out_.begin(u);
    }
  }

  int64_t left(int64_t u) const { return left_[size_t(u)]; }

  void take(int64_t e) {
    if (!taken_[size_t(e)]) {
      taken_[size_t(e)] = 1;
      --left_[size_t(src_[size_t(e)])];
    }
  }

  // An untaken out-edge of u, or -1.  Preferred, in this order: one that stays in u's
  // component and whose target keeps an untaken out-edge; one that stays; one whose
  // target keeps an untaken out-edge; the first.
  int64_t choose(int64_t u) {
    if (!left_[size_t(u)]) return -1;
    int64_t i = pos_[size_t(u)];
    while (taken_[size_t(out_.edges[size_t(i)])]) ++i;
    pos_[size_t(u)] = i;
    int64_t here = comp_[size_t(u)], best = -1, best_rank = 4;
    for (int64_t j = i; j < out_.end(u); ++j) {
      int64_t e = out_.edges[size_t(j)];
      if (taken_[size_t(e)]) continue;
      int64_t v = dst_[size_t(e)];
      int64_t rank = (comp_[size_t(v)] == here ? 0 : 2) + (left_[size_t(v)] > (v == u ? 1 : 0) ? 0 : 1);
      if (rank < best_rank) {
        best = e;
        best_rank = rank;
        if (rank == 0) break;
      }
    }
    return best;
  }

  // Shortest path from `start` to a node with an untaken out-edge, searching at most
  // `limit` nodes (the count includes every node discovered, as cover.py's `prev`).
  bool detour(int64_t start, int64_t limit, Ids& path) {
    ++gen_;
    stamp_[size_t(start)] = gen_;
    prev_[size_t(start)] = -1;
    int64_t discovered = 1;
    queue_.clear();
    queue_.push_back(start);
    while (!queue_.empty() && discovered <= limit) {
      int64_t u = queue_.front();
      queue_.pop_front();
      for (int64_t j = out_.begin(u); j < out_.end(u); ++j) {
        int64_t e = out_.edges[size_t(j)];
        int64_t v = dst_[size_t(e)];
        if (stamp_[size_t(v)] == gen_) continue;
        stamp_[size_t(v)] = gen_;
        prev_[size_t(v)] = e;
        ++discovered;
        if (left_[size_t(v)]) {
          path.clear();
          while (v != start) {
            path.push_back(prev_[size_t(v)]);
            v = src_[size_t(prev_[size_t(v)])];
          }
          std::reverse(path.begin(), path.end());
          return true;
        }
        queue_.push_back(v);
      }
    }
    return false;
  }

  int64_t dst(int64_t e) const { return dst_[size_t(e)]; }

 private:
  const Ids& src_;
  const Ids& dst_;
  OutEdges out_;
  std::vector<char> taken_;
  std::vector<int64_t> left_, pos_, comp_, stamp_, prev_;
  int64_t gen_ = 0;
  std::deque<int64_t> queue_;
};

// cover(n, src, dst, parent, order, max_len, detour_nodes) -> (starts, offsets, edges):
// trace k starts at node starts[k] and takes edges[offsets[k]:offsets[k+1]].  `parent`
// and `order` are the BFS tree of cover.py's bfs_tree (which reports unreachable edges).
py::tuple cover(int64_t n, const Ids& src, const Ids& dst, const Ids& parent, const Ids& order, int64_t max_len,
                int64_t detour_nodes) {
  if (src.size() != dst.size() || parent.size() != size_t(n)) throw std::invalid_argument("cover: inconsistent graph");
  for (size_t e = 0; e < src.size(); ++e)
    if (src[e] < 0 || src[e] >= n || dst[e] < 0 || dst[e] >= n) throw std::invalid_argument("cover: edge out of range");
  Ids starts, offsets{0}, edges, path, d;
  {
    py::gil_scoped_release unlocked;
    Walker w(n, src, dst);
    size_t k = 0;  // position in BFS order of the next node that may have untaken edges
    while (true) {
      while (k < order.size() && !w.left(order[k])) ++k;
      if (k == order.size()) break;
      int64_t node = order[k];
      // the BFS-tree path to `node`
      path.clear();
      int64_t start = node;
      while (parent[size_t(start)] != -1) {
        path.push_back(parent[size_t(start)]);
        start = src[size_t(parent[size_t(start)])];
      }
      std::reverse(path.begin(), path.end());
      for (int64_t e : path) w.take(e);
      int64_t fresh = 0;  // untaken edges taken by this trace: at least one, so the loop ends
      while (true) {
        int64_t e = w.choose(node);
        if (e == -1) {
          if (!w.detour(node, detour_nodes, d) || int64_t(path.size() + d.size()) >= max_len) break;
          for (int64_t x : d) w.take(x);
          path.insert(path.end(), d.begin(), d.end());
          node = w.dst(d.back());
          continue;
        }
        if (int64_t(path.size()) >= max_len && fresh) break;
        ++fresh;
        w.take(e);
        path.push_back(e);
        node = w.dst(e);
      }
      starts.push_back(start);
      edges.insert(edges.end(), path.begin(), path.end());
      offsets.push_back(int64_t(edges.size()));
    }
  }
  return py::make_tuple(starts, offsets, edges);
}

}  // namespace

PYBIND11_MODULE(_cover, m) {
  m.doc() = "The trace cover of conformance (safestate.conform.cover).";
  m.def("cover", &cover, py::arg("n"), py::arg("src"), py::arg("dst"), py::arg("parent"), py::arg("order"),
        py::arg("max_len"), py::arg("detour_nodes"),
        "Traces from the initial nodes that take every edge: (starts, offsets, edges).");
}
