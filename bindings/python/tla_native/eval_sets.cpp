// SPDX-License-Identifier: Apache-2.0
// Sets: a .. b, membership, union / intersection / difference, \subseteq, the set
// constructors, SUBSET / \X / [S -> T] / [a : S] enumerated, and membership in a set
// descriptor (a set that is never enumerated: Nat, Seq(S), [S -> T], ...).
#include <algorithm>

#include "engine.hpp"

namespace safestate::tla_native {

uint32_t Engine::range(Node* n, Ctx& c) {
  int64_t lo = integer(n->kids[0], c), hi = integer(n->kids[1], c);
  std::vector<uint32_t> el;
  for (int64_t i = lo; i <= hi; ++i) el.push_back(Store::mk_int(i, n->loc));
  return st.intern(K_SET, el.data(), uint32_t(el.size()));
}

uint32_t Engine::in_set(Node* n, Ctx& c) {
  uint32_t x = eval(n->kids[0], c);
  bool in = st.member(set(n->kids[1], c), x, n->loc);
  return in == (n->op == IN) ? kTrue : kFalse;
}

// Both operands are sorted in TLC's order: a union is their merge, an intersection or
// difference a subsequence of the first (no sorting).
uint32_t Engine::set_algebra(Node* n, Ctx& c) {
  uint32_t a = set(n->kids[0], c), b = set(n->kids[1], c);
  const uint32_t *x = st.items(a), *y = st.items(b);
  uint32_t na = st.len(a), nb = st.len(b);
  if (na != 0 && nb != 0) {  // TLC looks elements of one up in the other
    int ca = st.set_cls(a), cb = st.set_cls(b);
    if (ca >= 0 && cb >= 0 && ca != cb) Store::incomparable("check equality of", n->loc);
  }
  if (n->op == CUP && nb == 0) return a;
  if (n->op == CUP && na == 0) return b;
  size_t base = stk_.size();
  if (n->op == CUP) {
    uint32_t i = 0, j = 0;
    while (i < na && j < nb) {
      int o = x[i] == y[j] ? 0 : st.cmp(x[i], y[j]);
      stk_.push_back(o <= 0 ? x[i] : y[j]);
      if (o <= 0) ++i;
      if (o >= 0) ++j;
    }
    stk_.insert(stk_.end(), x + i, x + na);
    stk_.insert(stk_.end(), y + j, y + nb);
  } else {
    for (uint32_t i = 0; i < na; ++i)
      if (st.member(b, x[i], n->loc) == (n->op == CAP)) stk_.push_back(x[i]);
  }
  uint32_t out = st.intern(K_SET, stk_.data() + base, uint32_t(stk_.size() - base));
  stk_.resize(base);
  return out;
}

uint32_t Engine::subseteq(Node* n, Ctx& c) {
  uint32_t a = set(n->kids[0], c), b = set(n->kids[1], c);
  for (uint32_t i = 0; i < st.len(a); ++i)
    if (!st.member(b, st.items(a)[i], n->loc)) return kFalse;
  return kTrue;
}

uint32_t Engine::set_enum(Node* n, Ctx& c) {
  size_t base = stk_.size();
  for (Node* k : n->kids) {
    uint32_t v = eval(k, c);
    stk_.push_back(v);
  }
  uint32_t out = st.mk_set(stk_.data() + base, stk_.data() + stk_.size());
  stk_.resize(base);
  return out;
}

uint32_t Engine::set_filter(Node* n, Ctx& c) {
  uint32_t s = set(n->kids[0], c);
  std::vector<uint32_t> el;
  for (uint32_t i = 0; i < st.len(s); ++i) {
    uint32_t x = st.items(s)[i];
    slots[size_t(n->ints[0])] = x;
    if (boolean(n->kids[1], c, "set filter predicate")) el.push_back(x);
  }
  return st.intern(K_SET, el.data(), uint32_t(el.size()));  // a subsequence: still sorted
}

// ints: one slot per binder; kids: the binders' sets, then the expression.
uint32_t Engine::set_map(Node* n, Ctx& c) {
  size_t nb = n->ints.size();
  std::vector<uint32_t> sets(nb), pos(nb, 0), el;
  for (size_t b = 0; b < nb; ++b) {
    sets[b] = set(n->kids[b], c);
    if (st.len(sets[b]) == 0) return st.mk_set(el);
  }
  while (true) {
    for (size_t b = 0; b < nb; ++b) slots[size_t(n->ints[b])] = st.items(sets[b])[pos[b]];
    el.push_back(eval(n->kids[nb], c));
    size_t b = 0;
    while (b < nb && ++pos[b] == st.len(sets[b])) pos[b++] = 0;
    if (b == nb) return st.mk_set(el);
  }
}

uint32_t Engine::powerset(Node* n, Ctx& c) {
  uint32_t b = set(n->kids[0], c);
  uint32_t nb = st.len(b);
  if (nb > kMaxEnumBits) fail("SUBSET of a set this large is left to the Python engine", n->loc);
  std::vector<uint32_t> el, sub;
  std::vector<uint32_t> base(st.items(b), st.items(b) + nb);  // items may move: interning grows the pool
  for (uint64_t m = 0; m < (uint64_t(1) << nb); ++m) {
    sub.clear();
    for (uint32_t i = 0; i < nb; ++i)
      if (m >> i & 1) sub.push_back(base[i]);
    el.push_back(st.intern(K_SET, sub.data(), uint32_t(sub.size())));  // a subsequence: sorted
  }
  return st.mk_set(el);
}

uint32_t Engine::product(Node* n, Ctx& c) {
  size_t nf = n->kids.size();
  std::vector<uint32_t> sets(nf), pos(nf, 0), el, tup(nf);
  uint64_t total = 1;
  for (size_t f = 0; f < nf; ++f) {
    sets[f] = set(n->kids[f], c);
    total *= std::max<uint64_t>(st.len(sets[f]), 1);
    if (total > kMaxEnum) fail("a product this large is left to the Python engine", n->loc);
  }
  for (size_t f = 0; f < nf; ++f)
    if (st.len(sets[f]) == 0) return st.mk_set(el);
  while (true) {
    for (size_t f = 0; f < nf; ++f) tup[f] = st.items(sets[f])[pos[f]];
    el.push_back(st.mk_seq(tup));
    size_t f = 0;
    while (f < nf && ++pos[f] == st.len(sets[f])) pos[f++] = 0;
    if (f == nf) return st.mk_set(el);
  }
}

uint32_t Engine::fn_set(Node* n, Ctx& c) {
  uint32_t d = set(n->kids[0], c), r = set(n->kids[1], c);
  uint32_t nd = st.len(d), nr = st.len(r);
  std::vector<uint32_t> keys(st.items(d), st.items(d) + nd), el;
  uint64_t total = 1;
  for (uint32_t i = 0; i < nd && nr > 0; ++i) {
    total *= nr;
    if (total > kMaxEnum) fail("a function set this large is left to the Python engine", n->loc);
  }
  if (nd > 0 && nr == 0) return st.mk_set(el);
  bool seq = true;  // a sequence when the domain is 1..n (as mk_fun makes it)
  for (uint32_t i = 0; i < nd && seq; ++i) seq = Store::is_int(keys[i]) && Store::int_of(keys[i]) == int64_t(i) + 1;
  std::vector<uint32_t> pos(nd, 0), buf;
  while (true) {
    buf.clear();
    if (!seq) buf.insert(buf.end(), keys.begin(), keys.end());
    for (uint32_t i = 0; i < nd; ++i) buf.push_back(st.items(r)[pos[i]]);
    el.push_back(st.intern(seq ? K_SEQ : K_FUN, buf.data(), nd));
    uint32_t i = 0;
    while (i < nd && ++pos[i] == nr) pos[i++] = 0;
    if (i == nd) return st.mk_set(el);
  }
}

// [a : S, b : T] as a finite set of records (ints: the field names).
uint32_t Engine::rec_set(Node* n, Ctx& c) {
  size_t nf = n->ints.size();
  std::vector<uint32_t> sets(nf), pos(nf, 0), el;
  for (size_t f = 0; f < nf; ++f) {
    sets[f] = set(n->kids[f], c);
    if (st.len(sets[f]) == 0) return st.mk_set(el);
  }
  std::vector<std::pair<uint32_t, uint32_t>> kv(nf);
  while (true) {
    for (size_t f = 0; f < nf; ++f) kv[f] = {uint32_t(n->ints[f]), st.items(sets[f])[pos[f]]};
    auto rec = kv;
    el.push_back(st.mk_fun(rec));
    size_t f = 0;
    while (f < nf && ++pos[f] == st.len(sets[f])) pos[f++] = 0;
    if (f == nf) return st.mk_set(el);
  }
}

bool Engine::not_of_kind(uint32_t x, int loc) const {
  if (st.kind(x) != K_MV)
    fail("Attempted to check if a value of another kind is an element of Nat, Int or STRING", loc);
  return false;
}

// Items first .. first + count - 1 of x (a sequence's or set's elements, or a
// function's range after its domain) are each a member of the set `kid` describes.
bool Engine::items_members(uint32_t x, uint32_t first, uint32_t count, Node* kid, Ctx& c) {
  for (uint32_t i = first; i < first + count; ++i)
    if (!member_sd(st.items(x)[i], kid, c)) return false;
  return true;
}

bool Engine::member_sd(uint32_t x, Node* sd, Ctx& c) {
  switch (sd->op) {
    case SD_SET: return st.member(set(sd->kids[0], c), x, sd->loc);
    case SD_RANGE: {
      int64_t lo = integer(sd->kids[0], c), hi = integer(sd->kids[1], c);
      if (!Store::is_int(x)) {
        // TLC's IntervalValue.member: another kind than an integer or a model value is an error.
        if (lo <= hi && st.kind(x) != K_MV)
          fail("Attempted to check if a value of another kind is in an integer interval", sd->loc);
        return false;
      }
      int64_t v = Store::int_of(x);
      return v >= lo && v <= hi;
    }
    // Nat, Int, STRING: a value of another kind (not a model value) is TLC's error.
    case SD_NAT: return Store::is_int(x) ? Store::int_of(x) >= 0 : not_of_kind(x, sd->loc);
    case SD_INT: return Store::is_int(x) || not_of_kind(x, sd->loc);
    case SD_STRING: return st.kind(x) == K_STR || not_of_kind(x, sd->loc);
    case SD_CUP: return member_sd(x, sd->kids[0], c) || member_sd(x, sd->kids[1], c);
    case SD_CAP: return member_sd(x, sd->kids[0], c) && member_sd(x, sd->kids[1], c);
    case SD_DIFF: return member_sd(x, sd->kids[0], c) && !member_sd(x, sd->kids[1], c);
    case SD_SEQ: return st.kind(x) == K_SEQ && items_members(x, 0, st.len(x), sd->kids[0], c);
    case SD_FN: {
      uint32_t dom = set(sd->kids[0], c);
      Kind k = st.kind(x);
      if (k == K_SEQ) {
        if (st.len(dom) != st.len(x)) return false;
        for (uint32_t i = 0; i < st.len(x); ++i)
          if (!st.member(dom, Store::mk_int(i + 1, sd->loc), sd->loc)) return false;
        return items_members(x, 0, st.len(x), sd->kids[1], c);
      }
      if (k != K_FUN || st.len(x) != st.len(dom)) return false;
      uint32_t n = st.len(x);
      for (uint32_t i = 0; i < n; ++i)  // TLC compares the domains: kinds too
        if (!st.equal_walk(st.items(x)[i], st.items(dom)[i], sd->loc)) return false;
      return items_members(x, n, n, sd->kids[1], c);
    }
    case SD_REC: {
      if (st.kind(x) != K_FUN || st.len(x) != sd->ints.size()) return false;
      uint32_t n = st.len(x);
      for (size_t i = 0; i < sd->ints.size(); ++i) {
        uint32_t key = uint32_t(sd->ints[i]);
        uint32_t j = 0;
        while (j < n && st.items(x)[j] != key) ++j;
        if (j == n || !member_sd(st.items(x)[n + j], sd->kids[i], c)) return false;
      }
      return true;
    }
    case SD_SUBSET: return st.kind(x) == K_SET && items_members(x, 0, st.len(x), sd->kids[0], c);
    case SD_PRODUCT: {
      if (st.kind(x) != K_SEQ || st.len(x) != sd->kids.size()) return false;
      for (uint32_t i = 0; i < st.len(x); ++i)
        if (!member_sd(st.items(x)[i], sd->kids[i], c)) return false;
      return true;
    }
    default: fail("bad set descriptor", sd->loc);
  }
}

}  // namespace safestate::tla_native
