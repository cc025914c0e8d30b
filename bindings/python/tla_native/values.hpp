// SPDX-License-Identifier: Apache-2.0
// The values of the native core: interned (hash-consed) and named by 32-bit ids, small
// integers tagged inline.  Equal values have equal ids (every value is interned in its
// canonical form: a set's elements and a function's keys sorted in TLC's order, a
// function with domain 1..n a sequence), so equality is mostly an id comparison.
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base.hpp"

namespace safestate::tla_native {

struct Val {
  Kind kind;
  uint32_t off, len;  // off: a string's index in Store::names
  int64_t aux;        // rank of a string / model value in TLC's order
  uint64_t hash;
  const uint32_t* data;  // the items of a sequence, function or set
};

// The values by id, in blocks that never move: worker threads read values while
// another thread appends (under Store's lock), so no read may race a reallocation.
class ValTable {
 public:
  const Val& operator[](size_t i) const { return blocks_[i >> kBits][i & (kBlock - 1)]; }
  size_t size() const { return n_; }
  void push_back(const Val& v) {
    if ((n_ & (kBlock - 1)) == 0) {
      if ((n_ >> kBits) >= kBlocks) fail("too many distinct values for the native engine", 0);
      blocks_[n_ >> kBits].reset(new Val[kBlock]);
    }
    blocks_[n_ >> kBits][n_ & (kBlock - 1)] = v;
    ++n_;
  }

 private:
  static constexpr size_t kBits = 16, kBlock = size_t(1) << kBits, kBlocks = size_t(1) << 15;
  std::unique_ptr<std::unique_ptr<Val[]>[]> blocks_ = std::make_unique<std::unique_ptr<Val[]>[]>(kBlocks);
  size_t n_ = 0;
};

// The value store: interning, TLC's order and equality, membership.
class Store {
 public:
  ValTable vals;
  std::vector<std::string> names;  // string / model value text, by aux index
  // Set while worker threads search: interning then takes the lock (one table, one
  // lock; reads of interned values need none, their storage never moves).
  bool concurrent = false;

  Store();

  static bool is_int(uint32_t id) { return id & kIntTag; }
  static int64_t int_of(uint32_t id) { return int64_t(id & ~kIntTag) - kIntBias; }
  static uint32_t mk_int(int64_t v, int loc) {
    if (v < -kIntBias || v >= kIntBias) fail("integer overflow in the native engine", loc);
    return kIntTag | uint32_t(v + kIntBias);
  }
  Kind kind(uint32_t id) const { return is_int(id) ? K_INT : vals[id].kind; }
  uint32_t len(uint32_t id) const { return vals[id].len; }
  const uint32_t* items(uint32_t id) const { return vals[id].data; }

  uint32_t mk_str(Kind k, const std::string& s, int64_t rank);
  // The ranks of the strings the spec's modules name (Python's string_rank), for a
  // string made while checking: TLC interns every string of the spec when it parses it,
  // a string made later (ToString) when it is made, so it ranks after them all, in the
  // order made.
  std::unordered_map<std::string, int64_t> known_ranks;
  std::vector<uint32_t> made_strings;  // in the order made
  static constexpr int64_t kMadeRank = int64_t(1) << 40;
  uint32_t made_str(const std::string& s);
  // A string's or model value's text (names may grow in another thread meanwhile).
  std::string name_of(uint32_t id);

  // Interns a sequence, function (keys then values) or set whose items are canonical.
  uint32_t intern(Kind k, const uint32_t* it, uint32_t n) {
    uint32_t cnt = k == K_FUN ? 2 * n : n;
    uint64_t h = hash_ids(uint64_t(k) << 32 | n, it, cnt);
    std::unique_lock<std::mutex> lock(mu_, std::defer_lock);
    if (concurrent) lock.lock();
    size_t mask = table_.size() - 1;
    size_t pos = h & mask;
    while (table_[pos] != kUnset) {
      const Val& v = vals[table_[pos]];
      if (v.hash == h && v.kind == k && v.len == n && std::equal(it, it + cnt, v.data)) return table_[pos];
      pos = (pos + 1) & mask;
    }
    uint32_t id = uint32_t(vals.size());
    uint32_t* data = alloc(cnt);
    std::copy(it, it + cnt, data);
    vals.push_back({k, 0, n, 0, h, data});
    table_[pos] = id;
    if (++count_ * 2 > table_.size()) grow();
    return id;
  }

  // TLC's order (values.tlc_key): booleans, integers, strings, model values,
  // functions (length, keys, values; a sequence's keys sort first), sets.
  static int cls(Kind k) { return k == K_SEQ ? K_FUN : k; }
  // TLC's compareTo fails on values of incomparable kinds (a model value compares
  // with anything): so does cmp, at any depth of its walk.
  [[noreturn]] static void incomparable(const char* what, int loc) {
    fail(std::string("Attempted to ") + what + " values of incomparable kinds", loc);
  }
  int cmp(uint32_t a, uint32_t b) const;
  int cmp_list(uint32_t a, uint32_t b) const;
  int cmp_items(const uint32_t* x, const uint32_t* y, uint32_t n) const;

  uint32_t mk_set(std::vector<uint32_t>& el) { return mk_set(el.data(), el.data() + el.size()); }
  // The set of the ids in [b, e) (sorted and deduplicated in place).
  uint32_t mk_set(uint32_t* b, uint32_t* e);
  uint32_t mk_seq(const std::vector<uint32_t>& el) { return intern(K_SEQ, el.data(), uint32_t(el.size())); }
  // A function from (key, value) pairs; canonical: a sequence when the domain is 1..n.
  uint32_t mk_fun(std::vector<std::pair<uint32_t, uint32_t>>& kv);

  // Equal values have equal ids (every value is interned in its canonical form), so a
  // small set or domain is searched by id, a large one by TLC's order.
  static constexpr uint32_t kLinear = 32;
  bool set_has(uint32_t s, uint32_t x) const {
    const uint32_t* it = items(s);
    uint32_t lo = 0, hi = len(s);
    if (hi <= kLinear) return std::find(it, it + hi, x) != it + hi;
    while (lo < hi) {
      uint32_t mid = (lo + hi) / 2;
      int c = cmp(it[mid], x);
      if (c == 0) return true;
      if (c < 0) lo = mid + 1;
      else hi = mid;
    }
    return false;
  }
  // The class of a (homogeneous) set's elements other than model values, -1 if none
  // (sorted: model values are contiguous, so the first or the last one is another).
  int set_cls(uint32_t s) const {
    uint32_t n = len(s);
    if (n == 0) return -1;
    Kind k = kind(items(s)[0]);
    if (k == K_MV) k = kind(items(s)[n - 1]);
    return k == K_MV ? -1 : cls(k);
  }
  // x \in s as TLC: its binary search in s compares x with elements of s, an error
  // where their kinds are incomparable at any depth (1 \in BOOLEAN, <<TRUE>> \in
  // {<<1>>}).  Checked only where x is not found by id (member_slow).
  bool member(uint32_t s, uint32_t x, int loc) const { return set_has(s, x) || member_slow(s, x, loc); }
  bool member_slow(uint32_t s, uint32_t x, int loc) const;

  // A function of strings (inline: cmp asks it of every pair of functions it compares).
  bool is_record(uint32_t f) const {
    if (kind(f) != K_FUN || len(f) == 0) return false;
    const uint32_t* k = items(f);
    for (uint32_t i = 0; i < len(f); ++i)
      if (kind(k[i]) != K_STR) return false;
    return true;
  }
  // a a record, b a function or sequence that does not convert to one (<<>> does).
  bool record_against_non_record(uint32_t a, uint32_t b) const {
    if (!is_record(a)) return false;
    Kind kb = kind(b);
    return (kb == K_SEQ && len(b) > 0) || (kb == K_FUN && !is_record(b));
  }
  // a = b as TLC's equals for different ids (values.tlc_equals): see values.cpp.
  bool equal_walk(uint32_t a, uint32_t b, int loc) const;
  size_t bytes() const { return vals.size() * sizeof(Val) + pooled_ * 4 + table_.size() * 4; }

 private:
  std::mutex mu_;
  std::vector<std::unique_ptr<uint32_t[]>> chunks_;  // the items of all values; never moved
  uint32_t* free_ = nullptr;
  size_t left_ = 0, pooled_ = 0;
  uint32_t* alloc(size_t n) {
    if (n > left_) new_chunk(n);
    uint32_t* p = free_;
    free_ += n;
    left_ -= n;
    pooled_ += n;
    return p;
  }
  void new_chunk(size_t n);
  std::vector<uint32_t> table_;
  size_t count_ = 0;
  std::map<std::pair<int, std::string>, uint32_t> strings_;
  uint32_t add_str(Kind k, const std::string& s, int64_t rank);  // under the lock
  void grow();
};

}  // namespace safestate::tla_native
