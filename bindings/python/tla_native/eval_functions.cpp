// SPDX-License-Identifier: Apache-2.0
// Functions, records, tuples and sequences: application, EXCEPT, DOMAIN, the
// constructors, and the Sequences operators.
#include "engine.hpp"

namespace safestate::tla_native {

// Where f(x) is among f's items (a function's values follow its n keys); fails as
// applying f to x fails.
uint32_t Engine::value_index(uint32_t f, uint32_t x, int loc, std::atomic<uint32_t>* hint) const {
  Kind k = st.kind(f);
  if (k == K_SEQ) {
    if (Store::is_int(x)) {
      int64_t i = Store::int_of(x);
      if (i >= 1 && i <= int64_t(st.len(f))) return uint32_t(i - 1);
    }
    fail("Attempted to apply a sequence to an argument outside its domain", loc);
  }
  if (k != K_FUN) fail("Attempted to apply a non-function", loc);
  const uint32_t* it = st.items(f);
  uint32_t n = st.len(f);
  if (hint) {
    uint32_t h = hint->load(std::memory_order_relaxed);
    if (h < n && it[h] == x) return n + h;
  }
  if (n <= Store::kLinear) {  // equal keys have equal ids
    for (uint32_t i = 0; i < n; ++i)
      if (it[i] == x) {
        if (hint) hint->store(i, std::memory_order_relaxed);
        return n + i;
      }
    fail("Attempted to apply a function to an argument outside its domain", loc);
  }
  uint32_t lo = 0, hi = n;
  while (lo < hi) {
    uint32_t mid = (lo + hi) / 2;
    int c = st.cmp(it[mid], x);
    if (c == 0) {
      if (hint) hint->store(mid, std::memory_order_relaxed);
      return n + mid;
    }
    if (c < 0) lo = mid + 1;
    else hi = mid;
  }
  fail("Attempted to apply a function to an argument outside its domain", loc);
}

uint32_t Engine::update(uint32_t f, uint32_t x, uint32_t val, int loc) {
  Kind k = st.kind(f);
  if (k == K_SEQ) {
    if (Store::is_int(x)) {
      int64_t i = Store::int_of(x);
      uint32_t n = st.len(f);
      if (i >= 1 && i <= int64_t(n)) {
        buf_.assign(st.items(f), st.items(f) + n);
        buf_[size_t(i - 1)] = val;
        return st.mk_seq(buf_);
      }
    }
    fail("EXCEPT of an argument outside the sequence's domain", loc);
  }
  if (k != K_FUN) fail("EXCEPT of a non-function", loc);
  uint32_t n = st.len(f);
  const uint32_t* it = st.items(f);
  for (uint32_t i = 0; i < n; ++i)
    if (it[i] == x) {
      buf_.assign(it, it + 2 * n);
      buf_[n + i] = val;
      return st.intern(K_FUN, buf_.data(), n);
    }
  fail("EXCEPT of an argument outside the function's domain", loc);
}

// The domain of a function as a set.
uint32_t Engine::domain(uint32_t f, int loc) {
  std::vector<uint32_t> el;
  if (st.kind(f) == K_SEQ) {
    for (uint32_t i = 1; i <= st.len(f); ++i) el.push_back(Store::mk_int(i, loc));
  } else if (st.kind(f) == K_FUN) {
    el.assign(st.items(f), st.items(f) + st.len(f));
  } else {
    fail("DOMAIN of a non-function", loc);
  }
  return st.intern(K_SET, el.data(), uint32_t(el.size()));  // already in TLC order
}

uint32_t Engine::seq_of(uint32_t v, int loc, const char* what) {
  if (st.kind(v) == K_SEQ) return v;
  fail(std::string(what) + " of a value that is not a sequence", loc);
}

// EXCEPT along a path: kids[pos..pos+depth) are the keys, at the end @ = old value.
uint32_t Engine::except_path(Node* n, Ctx& c, uint32_t f, size_t pos, size_t depth, Node* val, int at_slot) {
  uint32_t key = eval(n->kids[pos], c);
  uint32_t old = apply(f, key, n->loc);
  return update(f, key, except_value(n, c, old, pos, depth, val, at_slot), n->loc);
}

// The new value at the end of the path whose first key is kids[pos] (old: its value).
uint32_t Engine::except_value(Node* n, Ctx& c, uint32_t old, size_t pos, size_t depth, Node* val, int at_slot) {
  if (depth > 1) return except_path(n, c, old, pos + 1, depth - 1, val, at_slot);
  uint32_t saved = slots[size_t(at_slot)];
  slots[size_t(at_slot)] = old;
  uint32_t nv = eval(val, c);
  slots[size_t(at_slot)] = saved;
  return nv;
}

// The domain's elements are distinct and in TLC's order: the keys need no sorting; a
// sequence when the domain is 1..n (as mk_fun makes it).
uint32_t Engine::fn_lit(Node* n, Ctx& c) {
  uint32_t s = set(n->kids[0], c);
  uint32_t nk = st.len(s);
  const uint32_t* keys = st.items(s);
  bool seq = true;
  for (uint32_t i = 0; i < nk && seq; ++i) seq = Store::is_int(keys[i]) && Store::int_of(keys[i]) == int64_t(i) + 1;
  size_t base = stk_.size();
  if (!seq) stk_.insert(stk_.end(), keys, keys + nk);
  size_t vals = stk_.size();
  stk_.resize(vals + nk);
  for (uint32_t i = 0; i < nk; ++i) {
    slots[size_t(n->ints[0])] = keys[i];
    uint32_t v = eval(n->kids[1], c);
    stk_[vals + i] = v;
  }
  uint32_t out = st.intern(seq ? K_SEQ : K_FUN, stk_.data() + base, nk);
  stk_.resize(base);
  return out;
}

uint32_t Engine::rec_lit(Node* n, Ctx& c) {
  size_t nf = n->kids.size();
  if (nf != 0 && n->rank.size() == nf) {  // keys, then values, in TLC's order
    size_t base = stk_.size();
    stk_.resize(base + 2 * nf);
    for (size_t i = 0; i < nf; ++i) stk_[base + n->rank[i]] = uint32_t(n->ints[i]);
    for (size_t i = 0; i < nf; ++i) {
      uint32_t v = eval(n->kids[i], c);
      stk_[base + nf + n->rank[i]] = v;
    }
    uint32_t out = st.intern(K_FUN, stk_.data() + base, uint32_t(nf));
    stk_.resize(base);
    return out;
  }
  std::vector<std::pair<uint32_t, uint32_t>> kv;
  for (size_t i = 0; i < n->kids.size(); ++i) kv.emplace_back(uint32_t(n->ints[i]), eval(n->kids[i], c));
  return st.mk_fun(kv);
}

uint32_t Engine::tuple(Node* n, Ctx& c) {
  size_t base = stk_.size();
  for (Node* k : n->kids) {
    uint32_t v = eval(k, c);
    stk_.push_back(v);
  }
  uint32_t out = st.intern(K_SEQ, stk_.data() + base, uint32_t(stk_.size() - base));
  stk_.resize(base);
  return out;
}

// ints: the @ slot, then per update its path depth; kids: base, then per update its
// keys and its value.  The updates go into one copy of f's items, interned once at the
// end (the same value as interning after each update: the keys never change).
uint32_t Engine::except(Node* n, Ctx& c) {
  uint32_t f = eval(n->kids[0], c);
  Kind k = st.kind(f);
  size_t pos = 1;
  int at_slot = int(n->ints[0]);
  if (k != K_FUN && k != K_SEQ) {  // an error once a key is evaluated, or f itself
    for (size_t u = 1; u < n->ints.size(); ++u) {
      size_t depth = size_t(n->ints[u]);
      f = except_path(n, c, f, pos, depth, n->kids[pos + depth], at_slot);
      pos += depth + 1;
    }
    return f;
  }
  uint32_t len = st.len(f);
  size_t base = stk_.size();
  stk_.insert(stk_.end(), st.items(f), st.items(f) + (k == K_FUN ? 2 * len : len));
  for (size_t u = 1; u < n->ints.size(); ++u) {
    size_t depth = size_t(n->ints[u]);
    Node* val = n->kids[pos + depth];
    uint32_t key = eval(n->kids[pos], c);
    size_t at = base + value_index(f, key, n->loc, &n->hint);
    uint32_t nv = except_value(n, c, stk_[at], pos, depth, val, at_slot);
    stk_[at] = nv;
    pos += depth + 1;
  }
  uint32_t out = st.intern(k, stk_.data() + base, len);
  stk_.resize(base);
  return out;
}

uint32_t Engine::seq_head(Node* n, Ctx& c) {
  uint32_t s = seq_of(eval(n->kids[0], c), n->loc, "Head");
  if (st.len(s) == 0) fail("Attempted to apply Head to the empty sequence", n->loc);
  return st.items(s)[0];
}

uint32_t Engine::seq_tail(Node* n, Ctx& c) {
  uint32_t s = seq_of(eval(n->kids[0], c), n->loc, "Tail");
  if (st.len(s) == 0) fail("Attempted to apply Tail to the empty sequence", n->loc);
  return st.intern(K_SEQ, st.items(s) + 1, st.len(s) - 1);
}

uint32_t Engine::seq_append(Node* n, Ctx& c) {
  uint32_t s = seq_of(eval(n->kids[0], c), n->loc, "Append");
  uint32_t x = eval(n->kids[1], c);
  buf_.assign(st.items(s), st.items(s) + st.len(s));
  buf_.push_back(x);
  return st.mk_seq(buf_);
}

uint32_t Engine::seq_concat(Node* n, Ctx& c) {
  uint32_t a = seq_of(eval(n->kids[0], c), n->loc, "\\o");
  uint32_t b = seq_of(eval(n->kids[1], c), n->loc, "\\o");
  buf_.assign(st.items(a), st.items(a) + st.len(a));
  buf_.insert(buf_.end(), st.items(b), st.items(b) + st.len(b));
  return st.mk_seq(buf_);
}

uint32_t Engine::seq_subseq(Node* n, Ctx& c) {
  uint32_t s = seq_of(eval(n->kids[0], c), n->loc, "SubSeq");
  int64_t m = integer(n->kids[1], c), k = integer(n->kids[2], c);
  if (m > k) return st.intern(K_SEQ, nullptr, 0);
  if (m < 1 || k > int64_t(st.len(s))) fail("SubSeq indices outside the sequence", n->loc);
  return st.intern(K_SEQ, st.items(s) + (m - 1), uint32_t(k - m + 1));
}

// ints: the test's parameter slot; kids: the sequence, the test's body.
uint32_t Engine::select_seq(Node* n, Ctx& c) {
  uint32_t s = seq_of(eval(n->kids[0], c), n->loc, "SelectSeq");
  std::vector<uint32_t> out;
  for (uint32_t i = 0; i < st.len(s); ++i) {
    uint32_t x = st.items(s)[i];
    slots[size_t(n->ints[0])] = x;
    if (boolean(n->kids[1], c, "test of SelectSeq")) out.push_back(x);
  }
  return st.mk_seq(out);
}

}  // namespace safestate::tla_native
