// SPDX-License-Identifier: Apache-2.0
// Expressions: the dispatch over every op but the leaves (Engine::eval reads those),
// and the families that are not sets, functions or sequences: primed variables, LET,
// booleans, integers, IF/CASE, quantifiers, CHOOSE, operator calls.  The one-line ops
// are evaluated in the switch itself; the others call their family's function.
#include "engine.hpp"

namespace safestate::tla_native {

#define ALWAYS_INLINE __attribute__((always_inline)) inline

ALWAYS_INLINE uint32_t Engine::primed(Node* n, Ctx& c) {
  uint32_t v = c.t ? c.t[n->ints[0]] : kUnset;
  if (v == kUnset) fail("a primed variable is read before it is assigned", n->loc);
  return v;
}

ALWAYS_INLINE uint32_t Engine::let_ref(Node* n, Ctx& c) {
  uint32_t& sl = slots[size_t(n->ints[0])];
  if (sl == kUnset) sl = eval(n->kids[0], c);
  return sl;
}

ALWAYS_INLINE uint32_t Engine::conjunction(Node* n, Ctx& c) {
  for (Node* k : n->kids)
    if (!boolean(k, c, "conjunct")) return kFalse;
  return kTrue;
}

ALWAYS_INLINE uint32_t Engine::disjunction(Node* n, Ctx& c) {
  for (Node* k : n->kids)
    if (boolean(k, c, "disjunct")) return kTrue;
  return kFalse;
}

// \div and % as TLC: the quotient rounded down, the remainder's sign the divisor's.
ALWAYS_INLINE uint32_t Engine::divide(Node* n, Ctx& c) {
  int64_t a = integer(n->kids[0], c), b = integer(n->kids[1], c);
  if (b <= 0 && n->op == MOD) fail("The second argument of % should be a positive number", n->loc);
  if (b == 0) fail("Attempted to divide by zero", n->loc);
  int64_t q = a / b, r = a % b;
  if (r != 0 && ((r < 0) != (b < 0))) {
    q -= 1;
    r += b;
  }
  return Store::mk_int(n->op == DIV ? q : r, n->loc);
}

uint32_t Engine::eval_node(Node* n, Ctx& c) {
  switch (n->op) {
    // leaves and scopes
    case PVAR: return primed(n, c);
    case LETREF: return let_ref(n, c);
    case LET:
      for (int64_t s : n->ints) slots[size_t(s)] = kUnset;
      return eval(n->kids[0], c);
    // booleans
    case NOT: return boolean(n->kids[0], c, "operand of ~") ? kFalse : kTrue;
    case AND: return conjunction(n, c);
    case OR: return disjunction(n, c);
    case IMPLIES:
      return !boolean(n->kids[0], c, "antecedent of =>") || boolean(n->kids[1], c, "consequent of =>") ? kTrue : kFalse;
    case EQUIV:
      return boolean(n->kids[0], c, "operand of <=>") == boolean(n->kids[1], c, "operand of <=>") ? kTrue : kFalse;
    case EQ: return equal(eval(n->kids[0], c), eval(n->kids[1], c), n->loc) ? kTrue : kFalse;
    case NEQ: return equal(eval(n->kids[0], c), eval(n->kids[1], c), n->loc) ? kFalse : kTrue;
    // integers
    case LT: return integer(n->kids[0], c) < integer(n->kids[1], c) ? kTrue : kFalse;
    case LE: return integer(n->kids[0], c) <= integer(n->kids[1], c) ? kTrue : kFalse;
    case GT: return integer(n->kids[0], c) > integer(n->kids[1], c) ? kTrue : kFalse;
    case GE: return integer(n->kids[0], c) >= integer(n->kids[1], c) ? kTrue : kFalse;
    case NEG: return Store::mk_int(-integer(n->kids[0], c), n->loc);
    case ADD: return Store::mk_int(integer(n->kids[0], c) + integer(n->kids[1], c), n->loc);
    case SUB: return Store::mk_int(integer(n->kids[0], c) - integer(n->kids[1], c), n->loc);
    case MUL: return Store::mk_int(integer(n->kids[0], c) * integer(n->kids[1], c), n->loc);
    case DIV:
    case MOD: return divide(n, c);
    // control, quantifiers, operator calls
    case IF: return eval(boolean(n->kids[0], c, "IF condition") ? n->kids[1] : n->kids[2], c);
    case CASE: return case_of(n, c);
    case FORALL:
    case EXISTS: return quantify(n, c);
    case CHOOSE: return choose(n, c);
    case BIND: bind(n, c); return eval(n->kids.back(), c);
    case BIND_MEMO: return call_memo(n, c);
    // sets (eval_sets.cpp)
    case RANGE: return range(n, c);
    case IN:
    case NOTIN: return in_set(n, c);
    case IN_SD: return member_sd(eval(n->kids[0], c), n->kids[1], c) == (n->ints[0] == 0) ? kTrue : kFalse;
    case CUP:
    case CAP:
    case DIFF: return set_algebra(n, c);
    case SUBSETEQ: return subseteq(n, c);
    case CARD: return Store::mk_int(st.len(set(n->kids[0], c)), n->loc);
    case SETENUM: return set_enum(n, c);
    case SETFILTER: return set_filter(n, c);
    case SETMAP: return set_map(n, c);
    case POWERSET: return powerset(n, c);
    case PRODUCT: return product(n, c);
    case FNSET: return fn_set(n, c);
    case RECSET: return rec_set(n, c);
    // functions, records, tuples, sequences (eval_functions.cpp)
    case FNAPP: return fn_app(n, c);
    case FNLIT: return fn_lit(n, c);
    case RECLIT: return rec_lit(n, c);
    case TUPLE: return tuple(n, c);
    case EXCEPT: return except(n, c);
    case DOMAIN: return domain(eval(n->kids[0], c), n->loc);
    case LEN: return Store::mk_int(st.len(seq_of(eval(n->kids[0], c), n->loc, "Len")), n->loc);
    case HEAD: return seq_head(n, c);
    case TAIL: return seq_tail(n, c);
    case APPEND: return seq_append(n, c);
    case CONCAT: return seq_concat(n, c);
    case SUBSEQ: return seq_subseq(n, c);
    case SELECTSEQ: return select_seq(n, c);
    // print.cpp
    case TOSTRING: return to_string(n, c);
    default: fail("not an expression", n->loc);
  }
}

uint32_t Engine::case_of(Node* n, Ctx& c) {
  size_t arms = size_t(n->ints[0]);
  for (size_t i = 0; i < arms; ++i)
    if (boolean(n->kids[2 * i], c, "CASE guard")) return eval(n->kids[2 * i + 1], c);
  if (n->kids.size() > 2 * arms) return eval(n->kids.back(), c);
  fail("Attempted to evaluate a CASE with no arm whose guard is true", n->loc);
}

uint32_t Engine::quantify(Node* n, Ctx& c) {
  uint32_t s = set(n->kids[0], c);
  bool want = n->op == EXISTS;
  for (uint32_t i = 0; i < st.len(s); ++i) {
    slots[size_t(n->ints[0])] = st.items(s)[i];
    if (boolean(n->kids[1], c, "quantified expression") == want) return want ? kTrue : kFalse;
  }
  return want ? kFalse : kTrue;
}

// The first element in TLC's order that satisfies the predicate.
uint32_t Engine::choose(Node* n, Ctx& c) {
  uint32_t s = set(n->kids[0], c);
  for (uint32_t i = 0; i < st.len(s); ++i) {
    slots[size_t(n->ints[0])] = st.items(s)[i];
    if (boolean(n->kids[1], c, "CHOOSE predicate")) return st.items(s)[i];
  }
  fail(
      "Attempted to compute the value of an expression of form CHOOSE x \\in S: P, but no element of S satisfied "
      "P",
      n->loc);
}

// The arguments on the scratch stack; the lookup reuses one key (no allocation unless
// the call is new).
uint32_t Engine::call_memo(Node* n, Ctx& c) {
  size_t na = n->ints.size(), base = stk_.size();
  for (size_t i = 0; i < na; ++i) {
    uint32_t a = eval(n->kids[i], c);
    stk_.push_back(a);
  }
  probe_.node = n;
  probe_.args.assign(stk_.begin() + ptrdiff_t(base), stk_.end());
  auto it = memo_.find(probe_);
  if (it != memo_.end()) {
    stk_.resize(base);
    return it->second;
  }
  for (size_t i = 0; i < na; ++i) slots[size_t(n->ints[i])] = stk_[base + i];
  uint32_t v = eval(n->kids.back(), c);
  memo_.emplace(MemoKey{n, std::vector<uint32_t>(stk_.begin() + ptrdiff_t(base), stk_.begin() + ptrdiff_t(base + na))},
                v);
  stk_.resize(base);
  return v;
}

#undef ALWAYS_INLINE

}  // namespace safestate::tla_native
