// SPDX-License-Identifier: Apache-2.0
// The program tree built from Python's tuples (shared subtrees built once), record
// literals' field order, constant folding.
#include <algorithm>

#include "engine.hpp"

namespace safestate::tla_native {

Node* Engine::build(py::handle obj) {
  if (obj.is_none()) return nullptr;
  auto it = built.find(obj.ptr());
  if (it != built.end()) return it->second;
  py::tuple t = obj.cast<py::tuple>();
  auto n = std::make_unique<Node>();
  n->op = t[0].cast<int>();
  n->loc = t[1].cast<int>();
  for (auto x : t[2].cast<py::tuple>()) n->ints.push_back(x.cast<int64_t>());
  if (!n->ints.empty()) n->a = n->ints[0];
  n->v = t[3].cast<uint32_t>();
  for (auto x : t[4].cast<py::tuple>()) n->kids.push_back(build(x));
  n->k = build(t[5]);
  Node* raw = n.get();
  if (raw->op == A_FORALL) {  // its last kid, the A_FORALL_NEXT its instances end in, points back
    raw->kids.back()->k = raw;
    if (size_t(raw->a) >= foralls_.size()) foralls_.resize(size_t(raw->a) + 1);
  }
  nodes.push_back(std::move(n));
  keep_.push_back(py::reinterpret_borrow<py::object>(obj));
  built[obj.ptr()] = raw;
  if (raw->op == RECLIT) rank_fields(raw);
  fold(raw);
  return raw;
}

// A record literal's fields in TLC's order, when its names are distinct strings.
void Engine::rank_fields(Node* n) {
  size_t nf = n->ints.size();
  std::vector<uint32_t> order(nf);
  for (size_t i = 0; i < nf; ++i) {
    uint32_t key = uint32_t(n->ints[i]);
    if (Store::is_int(key) || key >= st.vals.size() || st.kind(key) != K_STR) return;
    order[i] = uint32_t(i);
  }
  std::sort(order.begin(), order.end(),
            [&](uint32_t a, uint32_t b) { return st.cmp(uint32_t(n->ints[a]), uint32_t(n->ints[b])) < 0; });
  for (size_t i = 1; i < nf; ++i)
    if (n->ints[order[i]] == n->ints[order[i - 1]]) return;
  n->rank.assign(nf, 0);
  for (size_t r = 0; r < nf; ++r) n->rank[order[r]] = uint32_t(r);
}

// A node of a folding op (ops.def) whose kids are all constants becomes the constant
// it evaluates to; one whose evaluation fails is left as it is (evaluated, and the
// error reported, only if reached).
void Engine::fold(Node* n) {
  if (n->op < 0 || n->op >= OP_COUNT || !kOpFolds[n->op]) return;
  if (n->kids.empty() && n->op != SETENUM && n->op != TUPLE && n->op != RECLIT) return;
  for (Node* k : n->kids)
    if (k->op != CONST) return;
  Ctx c;
  try {
    n->v = eval(n, c);
  } catch (const EvalFailure&) {
    return;
  }
  n->op = CONST;
  n->kids.clear();
}

}  // namespace safestate::tla_native
