// SPDX-License-Identifier: Apache-2.0
// One step from a given state: the model side of conformance
// (python/safestate/conform/native_step.py).  An action run from a given state lists
// its successors (action leaf, the leaf's parameters as one interned tuple, the state,
// its VIEW or 0xFFFFFFFF without one); an expression (or several) is evaluated in a
// given state, with `binds` (slot, value id) set first.  An evaluation error raises
// StepError (the caller evaluates again in Python, which reports it exactly).
#include "engine.hpp"

namespace safestate::tla_native {

py::object Engine::state(size_t i) const {
  std::vector<uint32_t> out(arena.begin() + ptrdiff_t(i * size_t(nvars)),
                            arena.begin() + ptrdiff_t((i + 1) * size_t(nvars)));
  return py::cast(out);
}

py::list Engine::step(py::handle action, const std::vector<uint32_t>& state,
                      const std::vector<std::pair<int64_t, uint32_t>>& binds) {
  Node* n = prepare(action, state, binds);
  std::vector<uint32_t> t(size_t(nvars), kUnset);
  Ctx c{state.data(), t.data(), nullptr};
  collected_ = py::list();
  collect_ = true;
  struct Done {  // however exec ends, the engine's emits go to the search again and
                 // no list is left held (step runs with the GIL)
    Engine& e;
    ~Done() {
      e.collect_ = false;
      e.collected_ = py::object();
    }
  } done{*this};
  try {
    exec(n, c);
  } catch (const EvalFailure& e) {
    throw StepError(e.message);
  }
  py::list out = py::reinterpret_steal<py::list>(collected_.release());
  return out;
}

uint32_t Engine::evaluate(py::handle expr, const std::vector<uint32_t>& state,
                          const std::vector<std::pair<int64_t, uint32_t>>& binds) {
  Node* n = prepare(expr, state, binds);
  Ctx c{state.data(), nullptr, nullptr};
  try {
    return eval(n, c);
  } catch (const EvalFailure& e) {
    throw StepError(e.message);
  }
}

// Several expressions in one state (an adapter's projection): one call, one conversion.
std::vector<uint32_t> Engine::evaluate_all(py::list exprs, const std::vector<uint32_t>& state,
                                           const std::vector<std::pair<int64_t, uint32_t>>& binds) {
  std::vector<uint32_t> out;
  out.reserve(exprs.size());
  prepare(py::none(), state, binds);
  Ctx c{state.data(), nullptr, nullptr};
  try {
    for (auto x : exprs) out.push_back(eval(build(x), c));
  } catch (const EvalFailure& e) {
    throw StepError(e.message);
  }
  return out;
}

// A value for Python (values.py): its kind and its scalar or its items' ids.
py::tuple Engine::describe(uint32_t id) const {
  Kind k = st.kind(id);
  if (k == K_BOOL) return py::make_tuple(int(k), id == kTrue);
  if (k == K_INT) return py::make_tuple(int(k), Store::int_of(id));
  if (k == K_STR || k == K_MV) return py::make_tuple(int(k), st.names[st.vals[id].off]);
  std::vector<uint32_t> items(st.items(id), st.items(id) + (k == K_FUN ? 2 : 1) * st.len(id));
  return py::make_tuple(int(k), items);
}

Node* Engine::prepare(py::handle node, const std::vector<uint32_t>& state,
                      const std::vector<std::pair<int64_t, uint32_t>>& binds) {
  if (state.size() != size_t(nvars)) throw std::invalid_argument("a state of the wrong length");
  stk_.clear();
  Node* n = build(node);
  for (auto& b : binds) {
    if (b.first < 0) throw std::invalid_argument("a negative slot");
    if (size_t(b.first) >= slots.size()) slots.resize(size_t(b.first) + 1, kUnset);
    slots[size_t(b.first)] = b.second;
  }
  return n;
}

// A successor met while `step` runs an action: every variable must be assigned (as
// Model.check_complete requires).
void Engine::collect(Ctx& c, int lf, int loc) {
  for (int i = 0; i < nvars; ++i)
    if (c.t[i] == kUnset) fail("successor state is not completely specified", loc);
  buf_.clear();
  if (lf >= 0 && size_t(lf) < leaf_params.size())
    for (int64_t s : leaf_params[size_t(lf)]) buf_.push_back(slots[size_t(s)]);
  uint32_t params = st.mk_seq(buf_);
  py::tuple st_ids{size_t(nvars)};
  for (int i = 0; i < nvars; ++i) st_ids[size_t(i)] = py::int_(c.t[i]);
  Ctx sc{c.t, nullptr, nullptr};
  uint32_t key = view ? eval(view, sc) : kUnset;  // the successor's VIEW, for the caller's check
  py::tuple item = py::make_tuple(lf, params, st_ids, key);
  if (PyList_Append(collected_.ptr(), item.ptr()) != 0) throw py::error_already_set();
}

}  // namespace safestate::tla_native
