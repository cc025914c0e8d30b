// SPDX-License-Identifier: Apache-2.0
// Actions, in continuation-passing style (a node's k is what follows it): Init and Next
// make their states in the order the Python action compiler's closures make them, so
// the successors come in TLC's order; A_EMIT hands each one to the search, a worker,
// or the conformance step.
#include "search_inl.hpp"

namespace safestate::tla_native {

// x' = e: assigns x' when unassigned (and unassigns it after), else is a test.
__attribute__((always_inline)) inline void Engine::assign(Node* n, Ctx& c) {
  uint32_t v = eval(n->kids[0], c);
  uint32_t& cur = c.t[n->ints[0]];
  if (cur == kUnset) {
    cur = v;
    exec(n->k, c);
    c.t[n->ints[0]] = kUnset;
  } else if (equal(cur, v, n->loc)) {
    exec(n->k, c);
  }
}

// x' \in S: one branch per element when x' is unassigned, else membership.
__attribute__((always_inline)) inline void Engine::assign_in(Node* n, Ctx& c) {
  uint32_t i = uint32_t(n->ints[0]);
  if (c.t[i] == kUnset) {
    uint32_t s = set(n->kids[0], c);
    for (uint32_t j = 0; j < st.len(s); ++j) {
      c.t[i] = st.items(s)[j];
      exec(n->k, c);
    }
    c.t[i] = kUnset;
  } else if (member_sd(c.t[i], n->kids[1], c)) {
    exec(n->k, c);
  }
}

void Engine::exec(Node* n, Ctx& c) {
  switch (n->op) {
    case A_EMIT:
      if (collect_) collect(c, int(n->ints[0]), n->loc);
      else if (fresh_) offer(c, int(n->ints[0]));
      else on_emit(c, int(n->ints[0]));
      return;
    case A_FALSE: return;
    case A_GUARD:
      if (boolean(n->kids[0], c, "action conjunct")) exec(n->k, c);
      return;
    case A_OR:
      for (Node* b : n->kids) exec(b, c);
      return;
    case A_EXISTS: exists(n, c); return;
    case A_LET:
      for (int64_t s : n->ints) slots[size_t(s)] = kUnset;
      exec(n->kids[0], c);
      return;
    case A_ASSIGN: assign(n, c); return;
    case A_ASSIGN_IN: assign_in(n, c); return;
    case A_IF: exec(boolean(n->kids[0], c, "IF condition") ? n->kids[1] : n->kids[2], c); return;
    case A_CASE: case_action(n, c); return;
    case A_IMPLIES:
      if (boolean(n->kids[0], c, "antecedent of =>")) exec(n->kids[1], c);
      else exec(n->k, c);
      return;
    case A_BIND:
      bind(n, c);
      exec(n->kids.back(), c);
      return;
    case A_FORALL: forall(n, c); return;
    case A_FORALL_NEXT: forall_next(n->k, c); return;
    case A_ALLASSIGNED: all_assigned(n, c); return;
    default: fail("not an action", n->loc);
  }
}

// ints: one slot per binder; kids: the binders' sets, then the body.  TLC's
// ContextEnumerator: every set first, the FIRST binder turns fastest.
void Engine::exists(Node* n, Ctx& c) {
  size_t nb = n->ints.size();
  if (nb == 1) {
    uint32_t s = set(n->kids[0], c);
    for (uint32_t i = 0; i < st.len(s); ++i) {
      slots[size_t(n->ints[0])] = st.items(s)[i];
      exec(n->kids[1], c);
    }
    return;
  }
  std::vector<uint32_t> sets(nb), pos(nb, 0);
  for (size_t b = 0; b < nb; ++b) {
    sets[b] = set(n->kids[b], c);
    if (st.len(sets[b]) == 0) return;
  }
  while (true) {
    for (size_t b = 0; b < nb; ++b) slots[size_t(n->ints[b])] = st.items(sets[b])[pos[b]];
    exec(n->kids[nb], c);
    size_t b = 0;
    while (b < nb && ++pos[b] == st.len(sets[b])) pos[b++] = 0;
    if (b == nb) return;
  }
}

void Engine::case_action(Node* n, Ctx& c) {
  size_t arms = size_t(n->ints[0]);
  for (size_t i = 0; i < arms; ++i)
    if (boolean(n->kids[2 * i], c, "CASE guard")) {
      exec(n->kids[2 * i + 1], c);
      return;
    }
  if (n->kids.size() > 2 * arms) {
    exec(n->kids.back(), c);
    return;
  }
  fail("Attempted to evaluate a CASE with no arm whose guard is true", n->loc);
}

void Engine::all_assigned(Node* n, Ctx& c) {
  for (int i = 0; i < nvars; ++i)
    if (c.t[i] == kUnset) {
      exec(n->kids[0], c);
      return;
    }
  exec(n->kids[1], c);
}

// \A x \in S : A in an action is the conjunction of A for each x, as TLC takes it
// (Tool.getNextStates, ActionCompiler._forall): A with the first binding, then the
// others as pending conjuncts, which TLC's list takes last-first (x1, xn, ..., x2);
// a pending one is a boolean once every variable is assigned.  The node's fields:
// ops.def, A_FORALL.
void Engine::bind_forall(Node* f, const Forall& fr) {
  size_t nb = f->ints.size() - 3;
  for (size_t b = 0; b < nb; ++b) slots[size_t(f->ints[3 + b])] = fr.order[fr.pos * nb + b];
}

void Engine::forall(Node* n, Ctx& c) {
  size_t nb = n->ints.size() - 3;
  std::vector<uint32_t> sets(nb), pos(nb, 0), combos;
  for (size_t b = 0; b < nb; ++b) {
    sets[b] = set(n->kids[b], c);
    if (st.len(sets[b]) == 0) {
      exec(n->k, c);
      return;
    }
  }
  while (true) {  // TLC's ContextEnumerator: the first binder turns fastest
    for (size_t b = 0; b < nb; ++b) combos.push_back(st.items(sets[b])[pos[b]]);
    size_t b = 0;
    while (b < nb && ++pos[b] == st.len(sets[b])) pos[b++] = 0;
    if (b == nb) break;
  }
  size_t count = combos.size() / nb;
  Forall fr;
  fr.order.reserve(combos.size());
  fr.order.insert(fr.order.end(), combos.begin(), combos.begin() + ptrdiff_t(nb));
  for (size_t i = count; i-- > 1;)
    fr.order.insert(fr.order.end(), combos.begin() + ptrdiff_t(i * nb), combos.begin() + ptrdiff_t((i + 1) * nb));
  Forall& cur = foralls_[size_t(n->a)];
  std::swap(cur, fr);  // fr: an outer instance of this \A, if any (restored after)
  bind_forall(n, cur);
  exec(n->kids[nb], c);
  std::swap(foralls_[size_t(n->a)], fr);
}

void Engine::forall_next(Node* f, Ctx& c) {
  Forall& fr = foralls_[size_t(f->a)];
  if (fr.pos + 1 >= fr.order.size() / (f->ints.size() - 3)) {
    exec(f->k, c);
    return;
  }
  // A later instance goes on with the slot values of its own (restored after).
  size_t lo = size_t(f->ints[1]), hi = size_t(f->ints[2]);
  std::vector<uint32_t> saved(slots.begin() + ptrdiff_t(lo), slots.begin() + ptrdiff_t(hi));
  ++fr.pos;
  bind_forall(f, fr);
  bool unassigned = false;
  for (int i = 0; i < nvars && !unassigned; ++i) unassigned = c.t[i] == kUnset;
  size_t nb = f->ints.size() - 3;
  exec(unassigned ? f->kids[nb] : f->kids[nb + 1], c);
  Forall& back = foralls_[size_t(f->a)];  // the same instance: nested ones restored theirs
  --back.pos;
  bind_forall(f, back);
  std::copy(saved.begin(), saved.end(), slots.begin() + ptrdiff_t(lo));
}

}  // namespace safestate::tla_native
