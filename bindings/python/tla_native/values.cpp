// SPDX-License-Identifier: Apache-2.0
// The value store's out-of-line part: strings, TLC's order, sets and functions made
// canonical, TLC's equality walk, the interning table's growth.
#include "values.hpp"

#include <functional>

namespace safestate::tla_native {

Store::Store() {
  vals.push_back({K_BOOL, 0, 0, 0, 11, nullptr});
  vals.push_back({K_BOOL, 0, 0, 1, 13, nullptr});
  table_.assign(1024, kUnset);
}

uint32_t Store::mk_str(Kind k, const std::string& s, int64_t rank) {
  std::unique_lock<std::mutex> lock(mu_, std::defer_lock);
  if (concurrent) lock.lock();
  auto it = strings_.find(std::make_pair(int(k), s));
  if (it != strings_.end()) return it->second;
  return add_str(k, s, rank);
}

uint32_t Store::made_str(const std::string& s) {
  std::unique_lock<std::mutex> lock(mu_, std::defer_lock);
  if (concurrent) lock.lock();
  auto it = strings_.find(std::make_pair(int(K_STR), s));
  if (it != strings_.end()) return it->second;
  auto known = known_ranks.find(s);
  int64_t rank = known != known_ranks.end() ? known->second : kMadeRank + int64_t(made_strings.size());
  uint32_t id = add_str(K_STR, s, rank);
  made_strings.push_back(id);
  return id;
}

std::string Store::name_of(uint32_t id) {
  std::unique_lock<std::mutex> lock(mu_, std::defer_lock);
  if (concurrent) lock.lock();
  return names[vals[id].off];
}

int Store::cmp(uint32_t a, uint32_t b) const {
  if (a == b) return 0;
  Kind ka = kind(a), kb = kind(b);
  if (cls(ka) != cls(kb)) {
    if (ka != K_MV && kb != K_MV) incomparable("compare", 0);
    return cls(ka) < cls(kb) ? -1 : 1;
  }
  switch (ka) {
    case K_BOOL: return a < b ? -1 : 1;
    case K_INT: return int_of(a) < int_of(b) ? -1 : 1;
    case K_STR:
    case K_MV: return vals[a].aux < vals[b].aux ? -1 : (vals[a].aux > vals[b].aux ? 1 : 0);
    case K_SET: return cmp_list(a, b);
    default: break;
  }
  // TLC's RecordValue.compareTo fails on a function that is not a record whatever the
  // sizes; which operand TLC's sort makes the receiver is not known here, so either
  // orientation stops the core and the Python engine decides.
  if (record_against_non_record(a, b) || record_against_non_record(b, a)) incomparable("compare", 0);
  uint32_t na = len(a), nb = len(b);
  if (na != nb) return na < nb ? -1 : 1;
  if (ka != kb) return ka == K_SEQ ? -1 : 1;  // () < (keys...)
  if (ka == K_SEQ) return cmp_items(items(a), items(b), na);
  int c = cmp_items(items(a), items(b), na);
  return c != 0 ? c : cmp_items(items(a) + na, items(b) + nb, na);
}

int Store::cmp_list(uint32_t a, uint32_t b) const {
  uint32_t na = len(a), nb = len(b);
  if (na != nb) return na < nb ? -1 : 1;
  return cmp_items(items(a), items(b), na);
}

int Store::cmp_items(const uint32_t* x, const uint32_t* y, uint32_t n) const {
  for (uint32_t i = 0; i < n; ++i) {
    if (x[i] == y[i]) continue;  // equal ids: equal values (records of one shape share their keys)
    int c = cmp(x[i], y[i]);
    if (c) return c;
  }
  return 0;
}

uint32_t Store::mk_set(uint32_t* b, uint32_t* e) {
  // TLC sorts a new set with compareTo: elements of two kinds (besides model
  // values) meet in its sort, an error (std::sort need not compare that pair).
  int c0 = -1;
  for (const uint32_t* p = b; p != e; ++p) {
    Kind k = kind(*p);
    if (k == K_MV) continue;
    if (c0 < 0) c0 = cls(k);
    else if (cls(k) != c0) incomparable("compare", 0);
  }
  std::sort(b, e, [this](uint32_t x, uint32_t y) { return cmp(x, y) < 0; });
  e = std::unique(b, e);
  return intern(K_SET, b, uint32_t(e - b));
}

uint32_t Store::mk_fun(std::vector<std::pair<uint32_t, uint32_t>>& kv) {
  std::sort(kv.begin(), kv.end(), [this](auto& a, auto& b) { return cmp(a.first, b.first) < 0; });
  uint32_t n = uint32_t(kv.size());
  bool seq = true;
  for (uint32_t i = 0; i < n && seq; ++i) seq = is_int(kv[i].first) && int_of(kv[i].first) == int64_t(i) + 1;
  std::vector<uint32_t> buf;
  if (seq) {
    for (auto& p : kv) buf.push_back(p.second);
    return mk_seq(buf);
  }
  for (auto& p : kv) buf.push_back(p.first);
  for (auto& p : kv) buf.push_back(p.second);
  return intern(K_FUN, buf.data(), n);
}

// x not found by id in s: its kind differs from the elements', or it is a container,
// searched with cmp (which fails itself, as in a large set's search).
bool Store::member_slow(uint32_t s, uint32_t x, int loc) const {
  uint32_t n = len(s);
  if (n == 0 || n > kLinear) return false;
  Kind kx = kind(x);
  if (kx == K_MV) return false;
  int sc = set_cls(s);
  if (sc >= 0 && sc != cls(kx)) incomparable("compare", loc);
  if (kx == K_SEQ || kx == K_FUN || kx == K_SET) {
    const uint32_t* it = items(s);
    uint32_t lo = 0, hi = n;
    while (lo < hi) {
      uint32_t mid = (lo + hi) / 2;
      if (cmp(it[mid], x) < 0) lo = mid + 1;
      else hi = mid;
    }
  }
  return false;
}

// a = b as TLC's equals for different ids (so unequal values: every value is interned
// in its canonical form): its walk in its order (a set's size, then its elements in
// TLC's order; a tuple's length, then its items; a record's field names, then its
// fields; a function's keys, then its values), failing at the first pair of
// incomparable kinds it meets (<<1>> = <<TRUE>>), as values.tlc_equals.
bool Store::equal_walk(uint32_t a, uint32_t b, int loc) const {
  if (a == b) return true;
  Kind ka = kind(a), kb = kind(b);
  if (ka == K_MV || kb == K_MV) return false;
  if (cls(ka) != cls(kb)) incomparable("check equality of", loc);
  if (ka != K_SEQ && ka != K_FUN && ka != K_SET) return false;
  // TLC's RecordValue.equals: a record equals only what converts to a record (a
  // function of field names, or <<>>), else an error whatever the sizes.
  if (record_against_non_record(a, b)) incomparable("check equality of", loc);
  uint32_t n = len(a);
  if (n != len(b)) return false;
  const uint32_t *x = items(a), *y = items(b);
  if (ka == K_SET || (ka == K_SEQ && kb == K_SEQ)) {
    for (uint32_t i = 0; i < n; ++i)
      if (!equal_walk(x[i], y[i], loc)) return false;
    return true;
  }
  bool record = ka == K_FUN && kb == K_FUN;
  for (uint32_t i = 0; i < n && record; ++i) record = !is_int(x[i]) && kind(x[i]) == K_STR;
  if (record) {
    if (!std::equal(x, x + n, y)) return false;
  } else {
    for (uint32_t i = 0; i < n; ++i) {
      uint32_t kx = ka == K_SEQ ? mk_int(int64_t(i) + 1, loc) : x[i];
      uint32_t ky = kb == K_SEQ ? mk_int(int64_t(i) + 1, loc) : y[i];
      if (!equal_walk(kx, ky, loc)) return false;
    }
  }
  const uint32_t* vx = ka == K_SEQ ? x : x + n;
  const uint32_t* vy = kb == K_SEQ ? y : y + n;
  for (uint32_t i = 0; i < n; ++i)
    if (!equal_walk(vx[i], vy[i], loc)) return false;
  return true;
}

void Store::new_chunk(size_t n) {
  left_ = std::max<size_t>(n, size_t(1) << 18);
  chunks_.emplace_back(new uint32_t[left_]);
  free_ = chunks_.back().get();
}

uint32_t Store::add_str(Kind k, const std::string& s, int64_t rank) {
  uint32_t id = uint32_t(vals.size());
  names.push_back(s);
  vals.push_back({k, uint32_t(names.size() - 1), 0, rank, mix(k * 7919ULL, std::hash<std::string>()(s)), nullptr});
  strings_[std::make_pair(int(k), s)] = id;
  return id;
}

void Store::grow() {
  std::vector<uint32_t> old(table_.size() * 2, kUnset);
  old.swap(table_);
  size_t mask = table_.size() - 1;
  for (uint32_t id : old) {
    if (id == kUnset) continue;
    size_t pos = vals[id].hash & mask;
    while (table_[pos] != kUnset) pos = (pos + 1) & mask;
    table_[pos] = id;
  }
}

}  // namespace safestate::tla_native
