// SPDX-License-Identifier: Apache-2.0
// safestate._tla_native: the native core of `safestate check --engine native`
// (docs/checker-performance.md, "Design of the compiled core").
//
// Values are interned (hash-consed) and named by 32-bit ids; small integers are tagged
// inline.  A state is an array of ids in one arena that is also the breadth-first queue;
// the seen-set is open-addressing tables (shards by hash) of state indices over that
// arena (exact: the id arrays are compared on a hash hit).  With several workers the
// search is level by level in threads (Engine::search_levels), with the one worker's
// results.  Init, Next, invariants and constraints arrive
// from Python (python/safestate/checker/native/translate.py) as a tree of tuples
// (op, loc, ints, value id, kids, continuation) built in the same order as the Python
// action compiler's closures, so the successors come in TLC's order.  Any evaluation
// error ends the search with the error's text and location: the Python engine then
// re-checks the model for TLC's exact report (the Python evaluator is the reference).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <time.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

namespace py = pybind11;

namespace {

enum Kind : uint8_t { K_BOOL, K_INT, K_STR, K_MV, K_SEQ, K_FUN, K_SET };

constexpr uint32_t kIntTag = 0x80000000u;
constexpr int64_t kIntBias = int64_t(1) << 30;
constexpr uint32_t kFalse = 0, kTrue = 1;
constexpr uint32_t kUnset = 0xFFFFFFFFu;

struct EvalFailure {
  std::string message;
  int loc;
};

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

[[noreturn]] void fail(const std::string& msg, int loc) { throw EvalFailure{msg, loc}; }

inline uint64_t mix(uint64_t h, uint64_t x) {
  h ^= x + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  h *= 0xff51afd7ed558ccdULL;
  return h ^ (h >> 32);
}

// The hash of an id array: one xor and one multiply per id (a bijection of the running
// hash for each id), the high bits folded into the low ones at the end (tables index by
// the low bits).  Only a table's probe order depends on it, never a result.
inline uint64_t hash_ids(uint64_t seed, const uint32_t* x, size_t n) {
  constexpr uint64_t kMul = 0x9e3779b97f4a7c15ULL;
  uint64_t h = (seed + n) * kMul;
  for (size_t i = 0; i < n; ++i) h = (h ^ x[i]) * kMul;
  h ^= h >> 32;
  h *= 0xff51afd7ed558ccdULL;
  return h ^ (h >> 29);
}

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

// ------------------------------------------------------------------ the value store
class Store {
 public:
  ValTable vals;
  std::vector<std::string> names;  // string / model value text, by aux index
  // Set while worker threads search: interning then takes the lock (one table, one
  // lock; reads of interned values need none, their storage never moves).
  bool concurrent = false;

  Store() {
    vals.push_back({K_BOOL, 0, 0, 0, 11, nullptr});
    vals.push_back({K_BOOL, 0, 0, 1, 13, nullptr});
    table_.assign(1024, kUnset);
  }

  static bool is_int(uint32_t id) { return id & kIntTag; }
  static int64_t int_of(uint32_t id) { return int64_t(id & ~kIntTag) - kIntBias; }
  static uint32_t mk_int(int64_t v, int loc) {
    if (v < -kIntBias || v >= kIntBias) fail("integer overflow in the native engine", loc);
    return kIntTag | uint32_t(v + kIntBias);
  }
  Kind kind(uint32_t id) const { return is_int(id) ? K_INT : vals[id].kind; }
  uint32_t len(uint32_t id) const { return vals[id].len; }
  const uint32_t* items(uint32_t id) const { return vals[id].data; }

  uint32_t mk_str(Kind k, const std::string& s, int64_t rank) {
    std::unique_lock<std::mutex> lock(mu_, std::defer_lock);
    if (concurrent) lock.lock();
    auto it = strings_.find(std::make_pair(int(k), s));
    if (it != strings_.end()) return it->second;
    return add_str(k, s, rank);
  }
  // The ranks of the strings the spec's modules name (Python's string_rank), for a
  // string made while checking: TLC interns every string of the spec when it parses it,
  // a string made later (ToString) when it is made, so it ranks after them all, in the
  // order made.
  std::unordered_map<std::string, int64_t> known_ranks;
  std::vector<uint32_t> made_strings;  // in the order made
  static constexpr int64_t kMadeRank = int64_t(1) << 40;
  uint32_t made_str(const std::string& s) {
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
  // A string's or model value's text (names may grow in another thread meanwhile).
  std::string name_of(uint32_t id) {
    std::unique_lock<std::mutex> lock(mu_, std::defer_lock);
    if (concurrent) lock.lock();
    return names[vals[id].off];
  }

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
  int cmp(uint32_t a, uint32_t b) const {
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
  int cmp_list(uint32_t a, uint32_t b) const {
    uint32_t na = len(a), nb = len(b);
    if (na != nb) return na < nb ? -1 : 1;
    return cmp_items(items(a), items(b), na);
  }
  int cmp_items(const uint32_t* x, const uint32_t* y, uint32_t n) const {
    for (uint32_t i = 0; i < n; ++i) {
      if (x[i] == y[i]) continue;  // equal ids: equal values (records of one shape share their keys)
      int c = cmp(x[i], y[i]);
      if (c) return c;
    }
    return 0;
  }

  uint32_t mk_set(std::vector<uint32_t>& el) { return mk_set(el.data(), el.data() + el.size()); }
  // The set of the ids in [b, e) (sorted and deduplicated in place).
  uint32_t mk_set(uint32_t* b, uint32_t* e) {
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
  uint32_t mk_seq(const std::vector<uint32_t>& el) { return intern(K_SEQ, el.data(), uint32_t(el.size())); }
  // A function from (key, value) pairs; canonical: a sequence when the domain is 1..n.
  uint32_t mk_fun(std::vector<std::pair<uint32_t, uint32_t>>& kv) {
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
  // {<<1>>}).  Checked only where x is not found by id: its kind differs from the
  // elements', or it is a container, searched with cmp (which fails itself, as in a
  // large set's search).
  bool member(uint32_t s, uint32_t x, int loc) const {
    if (set_has(s, x)) return true;
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
  // a = b as TLC's equals for different ids (so unequal values: every value is
  // interned in its canonical form): its walk in its order (a set's size, then its
  // elements in TLC's order; a tuple's length, then its items; a record's field
  // names, then its fields; a function's keys, then its values), failing at the first
  // pair of incomparable kinds it meets (<<1>> = <<TRUE>>), as values.tlc_equals.
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
  bool equal_walk(uint32_t a, uint32_t b, int loc) const {
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
  size_t bytes() const { return vals.size() * sizeof(Val) + pooled_ * 4 + table_.size() * 4; }

 private:
  std::mutex mu_;
  std::vector<std::unique_ptr<uint32_t[]>> chunks_;  // the items of all values; never moved
  uint32_t* free_ = nullptr;
  size_t left_ = 0, pooled_ = 0;
  uint32_t* alloc(size_t n) {
    if (n > left_) {
      left_ = std::max<size_t>(n, size_t(1) << 18);
      chunks_.emplace_back(new uint32_t[left_]);
      free_ = chunks_.back().get();
    }
    uint32_t* p = free_;
    free_ += n;
    left_ -= n;
    pooled_ += n;
    return p;
  }
  std::vector<uint32_t> table_;
  size_t count_ = 0;
  std::map<std::pair<int, std::string>, uint32_t> strings_;
  uint32_t add_str(Kind k, const std::string& s, int64_t rank) {  // under the lock
    uint32_t id = uint32_t(vals.size());
    names.push_back(s);
    vals.push_back({k, uint32_t(names.size() - 1), 0, rank, mix(k * 7919ULL, std::hash<std::string>()(s)), nullptr});
    strings_[std::make_pair(int(k), s)] = id;
    return id;
  }

  void grow() {
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
};

// ------------------------------------------------------------------ the program tree
enum Op : int {
  // expressions
  CONST,
  VAR,
  PVAR,
  SLOT,
  LETREF,
  LET,
  NOT,
  NEG,
  AND,
  OR,
  IMPLIES,
  EQUIV,
  EQ,
  NEQ,
  LT,
  LE,
  GT,
  GE,
  ADD,
  SUB,
  MUL,
  DIV,
  MOD,
  RANGE,
  IN,
  NOTIN,
  CUP,
  CAP,
  DIFF,
  SUBSETEQ,
  IF,
  CASE,
  FORALL,
  EXISTS,
  SETENUM,
  SETFILTER,
  SETMAP,
  FNAPP,
  FNLIT,
  RECLIT,
  TUPLE,
  EXCEPT,
  AT,
  DOMAIN,
  LEN,
  HEAD,
  TAIL,
  APPEND,
  CONCAT,
  SUBSEQ,
  CARD,
  IN_SD,
  BIND,
  RECSET,
  // set descriptors (membership only)
  SD_SET,
  SD_RANGE,
  SD_SEQ,
  SD_FN,
  SD_REC,
  SD_NAT,
  SD_INT,
  SD_STRING,
  // actions
  A_EMIT,
  A_FALSE,
  A_GUARD,
  A_OR,
  A_EXISTS,
  A_LET,
  A_ASSIGN,
  A_ASSIGN_IN,
  A_IF,
  A_CASE,
  A_IMPLIES,
  A_ALLASSIGNED,
  A_BIND,
  // more set descriptors
  SD_CUP,
  SD_CAP,
  SD_DIFF,
  CHOOSE,
  SELECTSEQ,
  // an operator call whose body reads only its parameters (no state, no outer binder):
  // its value is remembered per argument values
  BIND_MEMO,
  // TLC's ToString: the value as TLC prints it
  TOSTRING,
  // \A over an action that branches: the conjunction of its instances (A_FORALL_NEXT
  // goes on to the next instance)
  A_FORALL,
  A_FORALL_NEXT,
  // SUBSET S, S1 \X S2 \X ..., [S -> T] as finite sets (as values: enumerated)
  POWERSET,
  PRODUCT,
  FNSET,
  // membership in SUBSET S, S1 \X S2 ...
  SD_SUBSET,
  SD_PRODUCT,
  OP_COUNT
};

struct Node {
  int op = 0;
  int loc = 0;
  std::vector<int64_t> ints;
  int64_t a = 0;  // ints[0] (a variable's or slot's index), read without the indirection
  uint32_t v = 0;
  std::vector<Node*> kids;
  Node* k = nullptr;
  // RECLIT with distinct field names: kid i's rank among the fields in TLC's order
  // (computed once when built, so the record is made without sorting).
  std::vector<uint32_t> rank;
  // FNAPP / EXCEPT: where the key was found last time (a record's field sits at the
  // same place in every record of its shape); checked before it is used, so any value
  // is correct.  Relaxed atomic: worker threads share the tree.
  std::atomic<uint32_t> hint{0};
};

struct Ctx {
  const uint32_t* s = nullptr;
  uint32_t* t = nullptr;
  uint32_t* L = nullptr;
};

class Engine;
using Emit = void (Engine::*)(Ctx&, int leaf);

// The new states of one level of a search with several workers, sharded by hash (a
// lock per shard).  Where two workers find the same state, the one with the smaller
// sort key (parent's position in the level, rank among its successors) is kept: the
// one worker's search finds it first, so its parent and action are the ones recorded.
struct Fresh {
  static constexpr size_t kShards = 64;
  struct Shard {
    std::mutex mu;
    std::vector<uint32_t> states, view_keys, table;
    std::vector<uint64_t> keys;
    std::vector<int32_t> leaves;
  };
  std::unique_ptr<Shard[]> shards{new Shard[kShards]};
  size_t lo = 0, hi = 0;
  std::atomic<size_t> next_parent{0};
  std::atomic<bool> stop{false};  // a violation, deadlock, error: the level is searched again by one worker
  void clear() {
    for (size_t i = 0; i < kShards; ++i) {
      Shard& sh = shards[i];
      sh.states.clear();
      sh.view_keys.clear();
      sh.keys.clear();
      sh.leaves.clear();
      sh.table.assign(64, kUnset);
    }
    stop = false;
  }
};

class Engine {
 public:
  std::shared_ptr<Store> store = std::make_shared<Store>();
  Store& st = *store;
  int nvars = 0;
  std::vector<uint32_t> slots;
  std::vector<std::unique_ptr<Node>> nodes;
  std::unordered_map<PyObject*, Node*> built;
  std::vector<std::string> loc_text;

  // ------------------------------------------------------------ building
  Node* build(py::handle obj) {
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

  // ------------------------------------------------------------ expressions
  bool boolean(Node* n, Ctx& c, const char* what) {
    uint32_t v = eval(n, c);
    if (v == kTrue) return true;
    if (v == kFalse) return false;
    fail(std::string("The ") + what + " is not a boolean", n->loc);
  }
  int64_t integer(Node* n, Ctx& c) {
    uint32_t v = eval(n, c);
    if (!Store::is_int(v)) fail("an integer was expected", n->loc);
    return Store::int_of(v);
  }
  uint32_t set(Node* n, Ctx& c) {
    uint32_t v = eval(n, c);
    if (st.kind(v) != K_SET) fail("a finite set was expected", n->loc);
    return v;
  }
  __attribute__((always_inline)) bool equal(uint32_t a, uint32_t b, int loc) const {
    if (a == b) return true;
    Kind ka = st.kind(a), kb = st.kind(b);
    if (Store::cls(ka) != Store::cls(kb)) {
      if (ka != K_MV && kb != K_MV) Store::incomparable("check equality of", loc);
      return false;
    }
    if (ka == K_SEQ || ka == K_FUN || ka == K_SET) return st.equal_walk(a, b, loc);
    return false;
  }
  uint32_t apply(uint32_t f, uint32_t x, int loc, std::atomic<uint32_t>* hint = nullptr) const {
    uint32_t i = value_index(f, x, loc, hint);
    return st.items(f)[i];
  }
  // Where f(x) is among f's items (a function's values follow its n keys); fails as
  // applying f to x fails.
  uint32_t value_index(uint32_t f, uint32_t x, int loc, std::atomic<uint32_t>* hint) const {
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
  uint32_t update(uint32_t f, uint32_t x, uint32_t val, int loc) {
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
  uint32_t domain(uint32_t f, int loc) {
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
  uint32_t seq_of(uint32_t v, int loc, const char* what) {
    if (st.kind(v) == K_SEQ) return v;
    fail(std::string(what) + " of a value that is not a sequence", loc);
  }
  // EXCEPT along a path: kids[pos..pos+depth) are the keys, at the end @ = old value.
  uint32_t except_path(Node* n, Ctx& c, uint32_t f, size_t pos, size_t depth, Node* val, int at_slot) {
    uint32_t key = eval(n->kids[pos], c);
    uint32_t old = apply(f, key, n->loc);
    return update(f, key, except_value(n, c, old, pos, depth, val, at_slot), n->loc);
  }
  // The new value at the end of the path whose first key is kids[pos] (old: its value).
  uint32_t except_value(Node* n, Ctx& c, uint32_t old, size_t pos, size_t depth, Node* val, int at_slot) {
    if (depth > 1) return except_path(n, c, old, pos + 1, depth - 1, val, at_slot);
    uint32_t saved = slots[size_t(at_slot)];
    slots[size_t(at_slot)] = old;
    uint32_t nv = eval(val, c);
    slots[size_t(at_slot)] = saved;
    return nv;
  }
  bool not_of_kind(uint32_t x, int loc) const {
    if (st.kind(x) != K_MV)
      fail("Attempted to check if a value of another kind is an element of Nat, Int or STRING", loc);
    return false;
  }
  bool member_sd(uint32_t x, Node* sd, Ctx& c) {
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
      case SD_SEQ: {
        if (st.kind(x) != K_SEQ) return false;
        for (uint32_t i = 0; i < st.len(x); ++i)
          if (!member_sd(st.items(x)[i], sd->kids[0], c)) return false;
        return true;
      }
      case SD_FN: {
        uint32_t dom = set(sd->kids[0], c);
        Kind k = st.kind(x);
        if (k == K_SEQ) {
          if (st.len(dom) != st.len(x)) return false;
          for (uint32_t i = 0; i < st.len(x); ++i)
            if (!st.member(dom, Store::mk_int(i + 1, sd->loc), sd->loc)) return false;
          for (uint32_t i = 0; i < st.len(x); ++i)
            if (!member_sd(st.items(x)[i], sd->kids[1], c)) return false;
          return true;
        }
        if (k != K_FUN || st.len(x) != st.len(dom)) return false;
        uint32_t n = st.len(x);
        for (uint32_t i = 0; i < n; ++i)  // TLC compares the domains: kinds too
          if (!st.equal_walk(st.items(x)[i], st.items(dom)[i], sd->loc)) return false;
        for (uint32_t i = 0; i < n; ++i)
          if (!member_sd(st.items(x)[n + i], sd->kids[1], c)) return false;
        return true;
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
      case SD_SUBSET: {
        if (st.kind(x) != K_SET) return false;
        for (uint32_t i = 0; i < st.len(x); ++i)
          if (!member_sd(st.items(x)[i], sd->kids[0], c)) return false;
        return true;
      }
      case SD_PRODUCT: {
        if (st.kind(x) != K_SEQ || st.len(x) != sd->kids.size()) return false;
        for (uint32_t i = 0; i < st.len(x); ++i)
          if (!member_sd(st.items(x)[i], sd->kids[i], c)) return false;
        return true;
      }
      default: fail("bad set descriptor", sd->loc);
    }
  }

  // The largest set SUBSET, \X and [S -> T] enumerate here (beyond: the Python engine).
  static constexpr uint32_t kMaxEnumBits = 20;
  static constexpr uint64_t kMaxEnum = uint64_t(1) << kMaxEnumBits;

  // The leaves (a constant, a variable, a bound name) without a call of the big
  // evaluator: most nodes are leaves, and its entry and exit cost more than they do.
  __attribute__((always_inline)) uint32_t eval(Node* n, Ctx& c) {
    switch (n->op) {
      case CONST: return n->v;
      case VAR: return c.s[n->a];
      case SLOT:
      case AT: return slots[size_t(n->a)];
      default: return eval_node(n, c);
    }
  }
  // Every node but the leaves, which eval() reads itself (its only caller).
  uint32_t eval_node(Node* n, Ctx& c) {
    switch (n->op) {
      case PVAR: {
        uint32_t v = c.t ? c.t[n->ints[0]] : kUnset;
        if (v == kUnset) fail("a primed variable is read before it is assigned", n->loc);
        return v;
      }
      case LETREF: {
        uint32_t& sl = slots[size_t(n->ints[0])];
        if (sl == kUnset) sl = eval(n->kids[0], c);
        return sl;
      }
      case LET: {
        for (int64_t s : n->ints) slots[size_t(s)] = kUnset;
        return eval(n->kids[0], c);
      }
      case NOT: return boolean(n->kids[0], c, "operand of ~") ? kFalse : kTrue;
      case NEG: return Store::mk_int(-integer(n->kids[0], c), n->loc);
      case AND:
        for (Node* k : n->kids)
          if (!boolean(k, c, "conjunct")) return kFalse;
        return kTrue;
      case OR:
        for (Node* k : n->kids)
          if (boolean(k, c, "disjunct")) return kTrue;
        return kFalse;
      case IMPLIES:
        return !boolean(n->kids[0], c, "antecedent of =>") || boolean(n->kids[1], c, "consequent of =>") ? kTrue
                                                                                                         : kFalse;
      case EQUIV:
        return boolean(n->kids[0], c, "operand of <=>") == boolean(n->kids[1], c, "operand of <=>") ? kTrue : kFalse;
      case EQ: return equal(eval(n->kids[0], c), eval(n->kids[1], c), n->loc) ? kTrue : kFalse;
      case NEQ: return equal(eval(n->kids[0], c), eval(n->kids[1], c), n->loc) ? kFalse : kTrue;
      case LT: return integer(n->kids[0], c) < integer(n->kids[1], c) ? kTrue : kFalse;
      case LE: return integer(n->kids[0], c) <= integer(n->kids[1], c) ? kTrue : kFalse;
      case GT: return integer(n->kids[0], c) > integer(n->kids[1], c) ? kTrue : kFalse;
      case GE: return integer(n->kids[0], c) >= integer(n->kids[1], c) ? kTrue : kFalse;
      case ADD: return Store::mk_int(integer(n->kids[0], c) + integer(n->kids[1], c), n->loc);
      case SUB: return Store::mk_int(integer(n->kids[0], c) - integer(n->kids[1], c), n->loc);
      case MUL: return Store::mk_int(integer(n->kids[0], c) * integer(n->kids[1], c), n->loc);
      case DIV:
      case MOD: {
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
      case RANGE: {
        int64_t lo = integer(n->kids[0], c), hi = integer(n->kids[1], c);
        std::vector<uint32_t> el;
        for (int64_t i = lo; i <= hi; ++i) el.push_back(Store::mk_int(i, n->loc));
        return st.intern(K_SET, el.data(), uint32_t(el.size()));
      }
      case IN:
      case NOTIN: {
        uint32_t x = eval(n->kids[0], c);
        bool in = st.member(set(n->kids[1], c), x, n->loc);
        return in == (n->op == IN) ? kTrue : kFalse;
      }
      case IN_SD: {
        uint32_t x = eval(n->kids[0], c);
        return member_sd(x, n->kids[1], c) == (n->ints[0] == 0) ? kTrue : kFalse;
      }
      case CUP:
      case CAP:
      case DIFF: {
        // Both operands are sorted in TLC's order: a union is their merge, an
        // intersection or difference a subsequence of the first (no sorting).
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
      case SUBSETEQ: {
        uint32_t a = set(n->kids[0], c), b = set(n->kids[1], c);
        for (uint32_t i = 0; i < st.len(a); ++i)
          if (!st.member(b, st.items(a)[i], n->loc)) return kFalse;
        return kTrue;
      }
      case IF: return eval(boolean(n->kids[0], c, "IF condition") ? n->kids[1] : n->kids[2], c);
      case CASE: {
        size_t arms = n->ints[0];
        for (size_t i = 0; i < arms; ++i)
          if (boolean(n->kids[2 * i], c, "CASE guard")) return eval(n->kids[2 * i + 1], c);
        if (n->kids.size() > 2 * arms) return eval(n->kids.back(), c);
        fail("Attempted to evaluate a CASE with no arm whose guard is true", n->loc);
      }
      case FORALL:
      case EXISTS: {
        uint32_t s = set(n->kids[0], c);
        bool want = n->op == EXISTS;
        for (uint32_t i = 0; i < st.len(s); ++i) {
          slots[size_t(n->ints[0])] = st.items(s)[i];
          if (boolean(n->kids[1], c, "quantified expression") == want) return want ? kTrue : kFalse;
        }
        return want ? kFalse : kTrue;
      }
      case SETENUM: {
        size_t base = stk_.size();
        for (Node* k : n->kids) {
          uint32_t v = eval(k, c);
          stk_.push_back(v);
        }
        uint32_t out = st.mk_set(stk_.data() + base, stk_.data() + stk_.size());
        stk_.resize(base);
        return out;
      }
      case SETFILTER: {
        uint32_t s = set(n->kids[0], c);
        std::vector<uint32_t> el;
        for (uint32_t i = 0; i < st.len(s); ++i) {
          uint32_t x = st.items(s)[i];
          slots[size_t(n->ints[0])] = x;
          if (boolean(n->kids[1], c, "set filter predicate")) el.push_back(x);
        }
        return st.intern(K_SET, el.data(), uint32_t(el.size()));  // a subsequence: still sorted
      }
      case SETMAP: {
        // ints: one slot per binder; kids: the binders' sets, then the expression.
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
      case FNAPP: {
        uint32_t f = eval(n->kids[0], c);
        uint32_t x = eval(n->kids[1], c);
        if (!Store::is_int(f)) {  // a record's field where it was last time: no call
          const Val& v = st.vals[f];
          uint32_t h = n->hint.load(std::memory_order_relaxed);
          if (v.kind == K_FUN && h < v.len && v.data[h] == x) return v.data[v.len + h];
        }
        return apply(f, x, n->loc, &n->hint);
      }
      case FNLIT: {
        // The domain's elements are distinct and in TLC's order: the keys need no
        // sorting; a sequence when the domain is 1..n (as mk_fun makes it).
        uint32_t s = set(n->kids[0], c);
        uint32_t nk = st.len(s);
        const uint32_t* keys = st.items(s);
        bool seq = true;
        for (uint32_t i = 0; i < nk && seq; ++i)
          seq = Store::is_int(keys[i]) && Store::int_of(keys[i]) == int64_t(i) + 1;
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
      case RECLIT: {
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
      case TUPLE: {
        size_t base = stk_.size();
        for (Node* k : n->kids) {
          uint32_t v = eval(k, c);
          stk_.push_back(v);
        }
        uint32_t out = st.intern(K_SEQ, stk_.data() + base, uint32_t(stk_.size() - base));
        stk_.resize(base);
        return out;
      }
      case EXCEPT: {
        // ints: the @ slot, then per update its path depth; kids: base, then per
        // update its keys and its value.
        // The updates go into one copy of f's items, interned once at the end (the
        // same value as interning after each update: the keys never change).
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
      case DOMAIN: return domain(eval(n->kids[0], c), n->loc);
      case LEN: return Store::mk_int(st.len(seq_of(eval(n->kids[0], c), n->loc, "Len")), n->loc);
      case HEAD: {
        uint32_t s = seq_of(eval(n->kids[0], c), n->loc, "Head");
        if (st.len(s) == 0) fail("Attempted to apply Head to the empty sequence", n->loc);
        return st.items(s)[0];
      }
      case TAIL: {
        uint32_t s = seq_of(eval(n->kids[0], c), n->loc, "Tail");
        if (st.len(s) == 0) fail("Attempted to apply Tail to the empty sequence", n->loc);
        return st.intern(K_SEQ, st.items(s) + 1, st.len(s) - 1);
      }
      case APPEND: {
        uint32_t s = seq_of(eval(n->kids[0], c), n->loc, "Append");
        uint32_t x = eval(n->kids[1], c);
        buf_.assign(st.items(s), st.items(s) + st.len(s));
        buf_.push_back(x);
        return st.mk_seq(buf_);
      }
      case CONCAT: {
        uint32_t a = seq_of(eval(n->kids[0], c), n->loc, "\\o");
        uint32_t b = seq_of(eval(n->kids[1], c), n->loc, "\\o");
        buf_.assign(st.items(a), st.items(a) + st.len(a));
        buf_.insert(buf_.end(), st.items(b), st.items(b) + st.len(b));
        return st.mk_seq(buf_);
      }
      case SUBSEQ: {
        uint32_t s = seq_of(eval(n->kids[0], c), n->loc, "SubSeq");
        int64_t m = integer(n->kids[1], c), k = integer(n->kids[2], c);
        if (m > k) return st.intern(K_SEQ, nullptr, 0);
        if (m < 1 || k > int64_t(st.len(s))) fail("SubSeq indices outside the sequence", n->loc);
        return st.intern(K_SEQ, st.items(s) + (m - 1), uint32_t(k - m + 1));
      }
      case CARD: return Store::mk_int(st.len(set(n->kids[0], c)), n->loc);
      case BIND: bind(n, c); return eval(n->kids.back(), c);
      case BIND_MEMO: {
        // The arguments on the scratch stack; the lookup reuses one key (no
        // allocation unless the call is new).
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
        memo_.emplace(
            MemoKey{n, std::vector<uint32_t>(stk_.begin() + ptrdiff_t(base), stk_.begin() + ptrdiff_t(base + na))}, v);
        stk_.resize(base);
        return v;
      }
      case CHOOSE: {  // the first element in TLC's order that satisfies the predicate
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
      case SELECTSEQ: {  // ints: the test's parameter slot; kids: the sequence, the test's body
        uint32_t s = seq_of(eval(n->kids[0], c), n->loc, "SelectSeq");
        std::vector<uint32_t> out;
        for (uint32_t i = 0; i < st.len(s); ++i) {
          uint32_t x = st.items(s)[i];
          slots[size_t(n->ints[0])] = x;
          if (boolean(n->kids[1], c, "test of SelectSeq")) out.push_back(x);
        }
        return st.mk_seq(out);
      }
      case POWERSET: {
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
      case PRODUCT: {
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
      case FNSET: {
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
        for (uint32_t i = 0; i < nd && seq; ++i)
          seq = Store::is_int(keys[i]) && Store::int_of(keys[i]) == int64_t(i) + 1;
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
      case TOSTRING: {
        std::string out;
        print(eval(n->kids[0], c), out);
        return st.made_str(out);
      }
      case RECSET: {
        // [a : S, b : T] as a finite set of records (ints: the field names).
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
      default: fail("not an expression", n->loc);
    }
  }

  // A value as TLC prints it (values.fmt): a function of strings as a record, another
  // function as (k :> v @@ ...); a set's elements and a function's keys are in TLC's
  // order already.
  void print(uint32_t v, std::string& out) {
    Kind k = st.kind(v);
    switch (k) {
      case K_BOOL: out += v == kTrue ? "TRUE" : "FALSE"; return;
      case K_INT: out += std::to_string(Store::int_of(v)); return;
      case K_MV: out += st.name_of(v); return;
      case K_STR:
        out += '"';
        for (char ch : st.name_of(v)) {
          if (ch == '\\') out += "\\\\";
          else if (ch == '"') out += "\\\"";
          else if (ch == '\n') out += "\\n";
          else out += ch;
        }
        out += '"';
        return;
      default: break;
    }
    uint32_t n = st.len(v);
    const uint32_t* it = st.items(v);
    if (k == K_FUN) {
      bool record = true;
      for (uint32_t i = 0; i < n && record; ++i) record = st.kind(it[i]) == K_STR;
      out += record ? "[" : "(";
      for (uint32_t i = 0; i < n; ++i) {
        if (i) out += record ? ", " : " @@ ";
        if (record) out += st.name_of(it[i]);
        else print(it[i], out);
        out += record ? " |-> " : " :> ";
        print(it[n + i], out);
      }
      out += record ? "]" : ")";
      return;
    }
    out += k == K_SEQ ? "<<" : "{";
    for (uint32_t i = 0; i < n; ++i) {
      if (i) out += ", ";
      print(it[i], out);
    }
    out += k == K_SEQ ? ">>" : "}";
  }

  // ------------------------------------------------------------ actions
  int emit_kind = 0;  // 0: init, 1: next
  void exec(Node* n, Ctx& c) {
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
      case A_EXISTS: {
        // ints: one slot per binder; kids: the binders' sets, then the body.
        // TLC's ContextEnumerator: every set first, the FIRST binder turns fastest.
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
      case A_LET:
        for (int64_t s : n->ints) slots[size_t(s)] = kUnset;
        exec(n->kids[0], c);
        return;
      case A_ASSIGN: {
        uint32_t v = eval(n->kids[0], c);
        uint32_t& cur = c.t[n->ints[0]];
        if (cur == kUnset) {
          cur = v;
          exec(n->k, c);
          c.t[n->ints[0]] = kUnset;
        } else if (equal(cur, v, n->loc)) {
          exec(n->k, c);
        }
        return;
      }
      case A_ASSIGN_IN: {
        uint32_t i = uint32_t(n->ints[0]);
        if (c.t[i] == kUnset) {
          uint32_t s = set(n->kids[0], c);
          for (uint32_t j = 0; j < st.len(s); ++j) {
            c.t[i] = st.items(s)[j];
            exec(n->k, c);
          }
          c.t[i] = kUnset;
        } else if (member_in(c.t[i], n->kids[1], c)) {
          exec(n->k, c);
        }
        return;
      }
      case A_IF: exec(boolean(n->kids[0], c, "IF condition") ? n->kids[1] : n->kids[2], c); return;
      case A_CASE: {
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
      case A_ALLASSIGNED:
        for (int i = 0; i < nvars; ++i)
          if (c.t[i] == kUnset) {
            exec(n->kids[0], c);
            return;
          }
        exec(n->kids[1], c);
        return;
      default: fail("not an action", n->loc);
    }
  }
  // \A x \in S : A in an action is the conjunction of A for each x, as TLC takes it
  // (Tool.getNextStates, ActionCompiler._forall): A with the first binding, then the
  // others as pending conjuncts, which TLC's list takes last-first (x1, xn, ..., x2);
  // a pending one is a boolean once every variable is assigned.
  // ints: the \A's index, the first and one past the last slot its body uses, the
  // binders' slots; kids: the binders' sets, the body as an action, the body as a
  // guard, the A_FORALL_NEXT both end in; k: what follows the conjunction.
  struct Forall {
    std::vector<uint32_t> order;  // the bindings, nb ids each, in the order taken
    size_t pos = 0;
  };
  std::vector<Forall> foralls_;  // per \A (a worker has its own)
  void bind_forall(Node* f, const Forall& fr) {
    size_t nb = f->ints.size() - 3;
    for (size_t b = 0; b < nb; ++b) slots[size_t(f->ints[3 + b])] = fr.order[fr.pos * nb + b];
  }
  void forall(Node* n, Ctx& c) {
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
  void forall_next(Node* f, Ctx& c) {
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

  // BIND_MEMO's values (per engine: a worker has its own).
  struct MemoKey {
    const Node* node;
    std::vector<uint32_t> args;
    bool operator==(const MemoKey& o) const { return node == o.node && args == o.args; }
  };
  struct MemoHash {
    size_t operator()(const MemoKey& k) const {
      uint64_t h = mix(0x51ed, uint64_t(reinterpret_cast<uintptr_t>(k.node)));
      for (uint32_t a : k.args) h = mix(h, a);
      return size_t(h);
    }
  };
  std::unordered_map<MemoKey, uint32_t, MemoHash> memo_;
  MemoKey probe_;

  // An operator's arguments, evaluated into its parameters' slots (ints) before the body.
  void bind(Node* n, Ctx& c) {
    for (size_t i = 0; i < n->ints.size(); ++i) {
      uint32_t v = eval(n->kids[i], c);
      slots[size_t(n->ints[i])] = v;
    }
  }
  bool member_in(uint32_t x, Node* sd, Ctx& c) { return member_sd(x, sd, c); }

  // A record literal's fields in TLC's order, when its names are distinct strings.
  void rank_fields(Node* n) {
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

  // ------------------------------------------------------------ folding constants
  void fold(Node* n) {
    bool also = n->op == TOSTRING || n->op == POWERSET || n->op == PRODUCT || n->op == FNSET;
    if ((n->op < NOT || n->op > RECSET || n->op == AT || n->op == BIND) && !also) return;
    if (n->kids.empty() && n->op != SETENUM && n->op != TUPLE && n->op != RECLIT) return;
    for (Node* k : n->kids)
      if (k->op != CONST) return;
    Ctx c;
    try {
      n->v = eval(n, c);
    } catch (const EvalFailure&) {
      return;  // evaluated (and reported) only if reached
    }
    n->op = CONST;
    n->kids.clear();
  }

  // ------------------------------------------------------------ the search
  std::vector<uint32_t> arena;  // nvars ids per state
  std::vector<int32_t> parent, leaf;
  std::vector<uint32_t> level_start;  // index of the first state of each level (1-based levels)
  // The seen-set, in shards by hash (Fresh's shards): at a level's barrier each worker
  // adds the new states of its own shards.
  struct SeenShard {
    std::vector<uint32_t> table;
    size_t count = 0;
  };
  std::vector<SeenShard> seen = std::vector<SeenShard>(Fresh::kShards);
  uint64_t generated = 0;
  size_t head = 0;
  Node* init = nullptr;
  Node* next = nullptr;
  std::vector<Node*> invariants, constraints, action_constraints;
  bool check_deadlock = true;
  size_t max_memory_mb = 0;
  py::object progress;

  // Outcome.
  std::string result = "success";
  int violated = -1;
  int64_t trace_to = -1;
  std::vector<uint32_t> extra;
  int extra_leaf = -1;
  bool initial_violation = false;
  std::string error;
  int error_loc = 0;
  int64_t error_state = -1;

  struct Stop {};

  size_t nstates() const { return nvars ? arena.size() / size_t(nvars) : parent.size(); }
  int max_level() const { return int(level_start.size()); }

  // With a VIEW the seen-set holds the view's value (one id per state), else the state.
  Node* view = nullptr;
  std::vector<uint32_t> view_keys;
  uint32_t view_key = 0;  // of the state being looked up
  const uint32_t* key_of(uint32_t idx) const {
    return view ? &view_keys[idx] : arena.data() + size_t(idx) * size_t(nvars);
  }
  int key_len() const { return view ? 1 : nvars; }
  uint64_t key_hash(const uint32_t* x) const { return hash_ids(0x12345, x, size_t(key_len())); }
  static size_t shard_of(uint64_t h) { return (h >> 40) % Fresh::kShards; }
  // Index of the state, or -1 after adding it to the seen-set (then the caller stores it).
  int64_t find_or_insert(const uint32_t* x) {
    uint64_t h = key_hash(x);
    int64_t found = find(x, h);
    if (found < 0) insert(h, uint32_t(nstates()));
    return found;
  }
  // The seen-set's index of a state (or view), -1 if it has none (read-only).
  int64_t find(const uint32_t* x, uint64_t h) const {
    const SeenShard& sh = seen[shard_of(h)];
    if (sh.table.empty()) return -1;
    size_t mask = sh.table.size() - 1;
    size_t pos = h & mask;
    while (sh.table[pos] != kUnset) {
      if (std::equal(x, x + key_len(), key_of(sh.table[pos]))) return sh.table[pos];
      pos = (pos + 1) & mask;
    }
    return -1;
  }
  // Adds a state known to be new (its key's hash h) to its shard.
  void insert(uint64_t h, uint32_t idx) {
    SeenShard& sh = seen[shard_of(h)];
    if ((sh.count + 1) * 2 > sh.table.size()) {
      std::vector<uint32_t> old(std::max<size_t>(sh.table.size() * 2, 256), kUnset);
      old.swap(sh.table);
      size_t mask = sh.table.size() - 1;
      for (uint32_t id : old) {
        if (id == kUnset) continue;
        size_t pos = key_hash(key_of(id)) & mask;
        while (sh.table[pos] != kUnset) pos = (pos + 1) & mask;
        sh.table[pos] = id;
      }
    }
    size_t mask = sh.table.size() - 1, pos = h & mask;
    while (sh.table[pos] != kUnset) pos = (pos + 1) & mask;
    sh.table[pos] = idx;
    ++sh.count;
  }
  void add(const uint32_t* x, int32_t par, int32_t lf, int lvl) {
    arena.insert(arena.end(), x, x + nvars);
    if (view) view_keys.push_back(view_key);
    parent.push_back(par);
    leaf.push_back(lf);
    if (lvl > max_level()) level_start.push_back(uint32_t(nstates() - 1));
    if (nstates() % 20000 == 0) periodic();
  }
  size_t rss_mb() const {
    std::ifstream f("/proc/self/statm");
    size_t pages = 0, rss = 0;
    f >> pages >> rss;
    return rss * 4096 / (1024 * 1024);
  }
  std::chrono::steady_clock::time_point last_progress = std::chrono::steady_clock::now();
  // Ctrl-C, SIGTERM: the search runs without the GIL, so Python's handlers run only
  // here; the exception they raise (KeyboardInterrupt, the CLI's Terminated) leaves
  // run() as it is, with the counts so far readable.
  void poll_signals() {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
  void periodic() {
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
  bool holds_all(const std::vector<Node*>& preds, Ctx& c, int* which) {
    for (size_t i = 0; i < preds.size(); ++i)
      if (!boolean(preds[i], c, "predicate")) {
        if (which) *which = int(i);
        return false;
      }
    return true;
  }

  // The state graph (`conform/graph.py`): one edge per successor inside the model, as
  // the Python engine lists them (source, target, action leaf, the leaf's parameters
  // as one interned tuple of their slots' values).  Only the one-worker search records.
  bool record_edges = false;
  std::vector<std::vector<int64_t>> leaf_params;  // per leaf: the slots of its parameters
  std::vector<uint32_t> edge_src, edge_dst, edge_leaf, edge_params;
  size_t initial_count = 0;  // the initial states are the first ones stored
  void record_edge(uint32_t src, uint32_t dst, int lf) {
    buf_.clear();
    if (size_t(lf) < leaf_params.size())
      for (int64_t s : leaf_params[size_t(lf)]) buf_.push_back(slots[size_t(s)]);
    edge_src.push_back(src);
    edge_dst.push_back(dst);
    edge_leaf.push_back(uint32_t(lf));
    edge_params.push_back(st.mk_seq(buf_));
  }

  // The labelled graph of `safestate mutate`'s difference search (mutate/graph.py): per
  // successor inside the model (and per initial state, source 0xFFFFFFFF), the source,
  // the stored target, and the values of `label_vars` in the successor itself as one
  // interned tuple -- under a VIEW the stored target may differ from it outside the
  // VIEW, and the search compares what the step produced.  Only the one-worker search.
  std::vector<int64_t> label_vars;
  std::vector<uint32_t> label_src, label_dst, label_val;
  void record_label(uint32_t src, uint32_t dst, const uint32_t* t) {
    buf_.clear();
    for (int64_t v : label_vars) buf_.push_back(t[size_t(v)]);
    label_src.push_back(src);
    label_dst.push_back(dst);
    label_val.push_back(st.mk_seq(buf_));
  }

  int cur_level = 0;
  uint64_t before = 0;
  void on_emit(Ctx& c, int lf) {
    ++generated;
    for (int i = 0; i < nvars; ++i)
      if (c.t[i] == kUnset) fail("successor state is not completely specified", 0);
    Ctx sc{c.t, nullptr, nullptr};
    bool in_model = holds_all(constraints, sc, nullptr);
    if (in_model && !action_constraints.empty() && emit_kind == 1) {
      Ctx ac{c.s, c.t, nullptr};
      in_model = holds_all(action_constraints, ac, nullptr);
    }
    bool is_new = true;
    int64_t idx = -1;
    if (in_model) {
      if (view) view_key = eval(view, sc);
      int64_t found = find_or_insert(view ? &view_key : c.t);
      if (found < 0) {
        idx = int64_t(nstates());
        add(c.t, emit_kind ? int32_t(head) : -1, emit_kind ? lf : -1, emit_kind ? cur_level + 1 : 1);
      } else {
        is_new = false;
      }
      if (record_edges && emit_kind == 1) record_edge(uint32_t(head), uint32_t(found < 0 ? idx : found), lf);
      if (!label_vars.empty())
        record_label(emit_kind ? uint32_t(head) : 0xFFFFFFFFu, uint32_t(found < 0 ? idx : found), c.t);
    }
    if (!is_new) return;
    int which = -1;
    if (!holds_all(invariants, sc, &which)) {
      result = "safety failure";
      violated = which;
      initial_violation = emit_kind == 0;
      if (idx >= 0) {
        trace_to = idx;
      } else {
        trace_to = emit_kind ? int64_t(head) : -1;
        extra.assign(c.t, c.t + nvars);
        extra_leaf = lf;
      }
      throw Stop{};
    }
  }

  void run() {
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
          std::vector<uint32_t> cur(arena.begin() + head * size_t(nvars), arena.begin() + (head + 1) * size_t(nvars));
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

  // ------------------------------------------------------------ several workers
  // Level by level: the workers expand the current level's states (parents handed out
  // in chunks) into Fresh; at the barrier the new states are sorted by key and stored
  // as the one worker would store them.  A level where a worker meets a violation,
  // deadlock or evaluation error is searched again by the one-worker loop (run()),
  // which stops where the one worker stops, with its counts and trace.
  int workers = 1;
  // CPU seconds: each worker's (in levels), and the levels' slowest worker's, summed
  // (the search's critical path, without the serial part: what wall time would be on idle cores).
  std::vector<double> worker_cpu;
  double critical_cpu = 0;
  double level_cpu_ = 0;

  void search_levels() {
    std::vector<std::unique_ptr<Engine>> team;
    for (int w = 0; w < workers; ++w) team.emplace_back(new Engine(*this, w));
    Fresh fresh;
    worker_cpu.assign(size_t(workers), 0.0);
    st.concurrent = true;
    while (head < nstates()) {
      while (size_t(cur_level) < level_start.size() && head >= level_start[size_t(cur_level)]) ++cur_level;
      fresh.clear();
      fresh.lo = head;
      fresh.hi = nstates();
      fresh.next_parent = head;
      std::vector<std::thread> threads;
      for (int w = 1; w < workers; ++w) threads.emplace_back(&Engine::work, team[size_t(w)].get(), &fresh);
      team[0]->work(&fresh);
      for (auto& th : threads) th.join();
      double slowest = 0;
      for (size_t w = 0; w < team.size(); ++w) {
        worker_cpu[w] += team[w]->level_cpu_;
        slowest = std::max(slowest, team[w]->level_cpu_);
      }
      critical_cpu += slowest;
      if (fresh.stop) break;  // run() searches this level again with one worker
      for (auto& w : team) {
        generated += w->generated;
        w->generated = 0;
      }
      store_level(fresh, team);
    }
    st.concurrent = false;
  }

  // A worker: a view of the searching engine with its own scratch (slots, buffers).
  Engine(Engine& m, int) : store(m.store), nvars(m.nvars), slots(m.slots) {
    init = m.init;
    next = m.next;
    invariants = m.invariants;
    constraints = m.constraints;
    action_constraints = m.action_constraints;
    check_deadlock = m.check_deadlock;
    view = m.view;
    emit_kind = 1;
    foralls_.resize(m.foralls_.size());
    master_ = &m;
  }
  Engine() = default;

  void work(Fresh* f) {
    constexpr size_t kChunk = 16;
    std::vector<uint32_t> t(size_t(nvars), kUnset);
    fresh_ = f;
    double cpu0 = thread_cpu_seconds();
    const Engine& m = *master_;
    try {
      try {
        while (!f->stop.load(std::memory_order_relaxed)) {
          size_t p0 = f->next_parent.fetch_add(kChunk);
          if (p0 >= f->hi) break;
          for (size_t p = p0; p < std::min(p0 + kChunk, f->hi); ++p) {
            Ctx nc{m.arena.data() + p * size_t(nvars), t.data(), nullptr};
            parent_ = p - f->lo;
            rank_ = 0;
            before = generated;
            exec(next, nc);
            if (generated == before && check_deadlock) throw Stop{};
          }
        }
      } catch (const EvalFailure&) {
        f->stop = true;
      }
    } catch (const Stop&) {
      f->stop = true;
    }
    fresh_ = nullptr;
    level_cpu_ = thread_cpu_seconds() - cpu0;
  }

  // A successor found by a worker: new unless seen (in an earlier level, or earlier
  // in this one by the one worker's order); a new state's invariants are checked.
  void offer(Ctx& c, int lf) {
    ++generated;
    uint64_t key = (uint64_t(parent_) << 32) | rank_++;
    for (int i = 0; i < nvars; ++i)
      if (c.t[i] == kUnset) fail("successor state is not completely specified", 0);
    Ctx sc{c.t, nullptr, nullptr};
    bool in_model = holds_all(constraints, sc, nullptr);
    if (in_model && !action_constraints.empty()) {
      Ctx ac{c.s, c.t, nullptr};
      in_model = holds_all(action_constraints, ac, nullptr);
    }
    if (in_model) {
      uint32_t vk = view ? eval(view, sc) : 0;
      const uint32_t* x = view ? &vk : c.t;
      uint64_t h = master_->key_hash(x);
      if (master_->find(x, h) >= 0 || !keep(x, h, c.t, vk, key, lf)) return;
    }
    if (!holds_all(invariants, sc, nullptr)) throw Stop{};
  }

  // Stores the state in its shard of Fresh; false if the shard has it with a smaller key.
  bool keep(const uint32_t* x, uint64_t h, const uint32_t* state, uint32_t vk, uint64_t key, int lf) {
    Fresh::Shard& sh = fresh_->shards[shard_of(h)];
    std::lock_guard<std::mutex> lock(sh.mu);
    size_t mask = sh.table.size() - 1, pos = h & mask;
    int kl = key_len();
    auto key_at = [&](uint32_t i) { return view ? &sh.view_keys[i] : &sh.states[size_t(i) * size_t(nvars)]; };
    while (sh.table[pos] != kUnset) {
      uint32_t i = sh.table[pos];
      if (std::equal(x, x + kl, key_at(i))) {
        if (sh.keys[i] < key) return false;
        sh.keys[i] = key;
        sh.leaves[i] = lf;
        std::copy(state, state + nvars, sh.states.begin() + ptrdiff_t(i) * nvars);
        return true;
      }
      pos = (pos + 1) & mask;
    }
    uint32_t i = uint32_t(sh.keys.size());
    sh.table[pos] = i;
    sh.keys.push_back(key);
    sh.leaves.push_back(lf);
    sh.states.insert(sh.states.end(), state, state + nvars);
    if (view) sh.view_keys.push_back(vk);
    if ((i + 1) * 2 > sh.table.size()) {
      sh.table.assign(sh.table.size() * 2, kUnset);
      mask = sh.table.size() - 1;
      for (uint32_t j = 0; j <= i; ++j) {
        const uint32_t* y = key_at(j);
        size_t q = master_->key_hash(y) & mask;
        while (sh.table[q] != kUnset) q = (q + 1) & mask;
        sh.table[q] = j;
      }
    }
    return true;
  }

  // The barrier: the level's new states, in the one worker's order, stored; then each
  // worker adds those of its shards to the seen-set.
  void store_level(Fresh& f, std::vector<std::unique_ptr<Engine>>& team) {
    // Sorted by key: bucketed by parent (counting sort), each parent's few by rank.
    size_t nparents = f.hi - f.lo, total = 0;
    std::vector<uint32_t> start(nparents + 1, 0);
    for (size_t s = 0; s < Fresh::kShards; ++s)
      for (uint64_t key : f.shards[s].keys) ++start[(key >> 32) + 1], ++total;
    for (size_t p = 0; p < nparents; ++p) start[p + 1] += start[p];
    std::vector<std::pair<uint64_t, uint64_t>> order(total);  // (key, shard << 32 | index)
    for (size_t s = 0; s < Fresh::kShards; ++s)
      for (size_t i = 0; i < f.shards[s].keys.size(); ++i) {
        uint64_t key = f.shards[s].keys[i];
        order[start[key >> 32]++] = {key, (uint64_t(s) << 32) | i};
      }
    for (size_t p = 0, b = 0; p < nparents; b = start[p++])
      if (start[p] - b > 1) std::sort(order.begin() + ptrdiff_t(b), order.begin() + start[p]);
    for (auto& o : order) {
      Fresh::Shard& sh = f.shards[o.second >> 32];
      size_t i = o.second & 0xFFFFFFFFu;
      const uint32_t* x = &sh.states[i * size_t(nvars)];
      if (view) view_key = sh.view_keys[i];
      sh.keys[i] = nstates();  // now the state's index
      add(x, int32_t(f.lo + (o.first >> 32)), sh.leaves[i], cur_level + 1);
    }
    head = f.hi;
    std::vector<double> cpu(team.size(), 0.0);
    auto index = [this, &f, &cpu](size_t w) {
      double cpu0 = thread_cpu_seconds();
      for (size_t s = w; s < Fresh::kShards; s += size_t(workers))
        for (uint64_t idx : f.shards[s].keys) insert(key_hash(key_of(uint32_t(idx))), uint32_t(idx));
      cpu[w] = thread_cpu_seconds() - cpu0;
    };
    std::vector<std::thread> threads;
    for (size_t w = 1; w < team.size(); ++w) threads.emplace_back(index, w);
    index(0);
    for (auto& th : threads) th.join();
    for (size_t w = 0; w < cpu.size(); ++w) worker_cpu[w] += cpu[w];
    critical_cpu += *std::max_element(cpu.begin(), cpu.end());
  }

  py::object state(size_t i) const {
    std::vector<uint32_t> out(arena.begin() + i * size_t(nvars), arena.begin() + (i + 1) * size_t(nvars));
    return py::cast(out);
  }
  // ------------------------------------------------------------ one step from a given state
  // The model side of conformance (python/safestate/conform/native_step.py): an action
  // run from a given state lists its successors (action leaf, the leaf's parameters as
  // one interned tuple, the state, its VIEW or 0xFFFFFFFF without one), an expression
  // (or several) evaluated in a given state, with
  // `binds` (slot, value id) set first.  An evaluation error raises StepError (the
  // caller evaluates again in Python, which reports it exactly).
  py::list step(py::handle action, const std::vector<uint32_t>& state,
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
  uint32_t evaluate(py::handle expr, const std::vector<uint32_t>& state,
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
  std::vector<uint32_t> evaluate_all(py::list exprs, const std::vector<uint32_t>& state,
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
  struct StepError : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

  py::tuple describe(uint32_t id) const {
    Kind k = st.kind(id);
    if (k == K_BOOL) return py::make_tuple(int(k), id == kTrue);
    if (k == K_INT) return py::make_tuple(int(k), Store::int_of(id));
    if (k == K_STR || k == K_MV) return py::make_tuple(int(k), st.names[st.vals[id].off]);
    std::vector<uint32_t> items(st.items(id), st.items(id) + (k == K_FUN ? 2 : 1) * st.len(id));
    return py::make_tuple(int(k), items);
  }

 private:
  Node* prepare(py::handle node, const std::vector<uint32_t>& state,
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
  // A successor met while `step` runs an action: every variable must be assigned
  // (as Model.check_complete requires).
  void collect(Ctx& c, int lf, int loc) {
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
  bool collect_ = false;
  // Null outside `step` (which holds the GIL): a worker engine is made and destroyed
  // without the GIL, so no member may create or free a Python object.
  py::object collected_;
  std::vector<uint32_t> buf_;
  // Scratch of the expression being evaluated: each user appends its items at the end
  // and truncates back (indices, not pointers, are held across a nested eval, which
  // may grow it).  An evaluation error leaves items behind: cleared at each entry.
  std::vector<uint32_t> stk_;
  std::vector<py::object> keep_;
  Fresh* fresh_ = nullptr;  // set in a worker during a level
  const Engine* master_ = nullptr;
  size_t parent_ = 0;
  uint32_t rank_ = 0;
};

py::bytes as_bytes(const std::vector<uint32_t>& v) {
  return py::bytes(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(uint32_t));
}

size_t seen_bytes(const Engine& e) {
  size_t n = 0;
  for (auto& sh : e.seen) n += sh.table.capacity() * 4;
  return n;
}

}  // namespace

PYBIND11_MODULE(_tla_native, m) {
  m.doc() = "The native core of safestate check --engine native.";
  // The Python translator numbers the ops in the same order (checker/native/ops.py checks these).
  m.attr("OP_COUNT") = int(OP_COUNT);
  m.attr("OP_IN_SD") = int(IN_SD);
  m.attr("OP_SD_STRING") = int(SD_STRING);
  m.attr("OP_A_BIND") = int(A_BIND);
  m.attr("OP_SELECTSEQ") = int(SELECTSEQ);
  m.attr("OP_BIND_MEMO") = int(BIND_MEMO);
  m.attr("OP_TOSTRING") = int(TOSTRING);
  m.attr("OP_A_FORALL_NEXT") = int(A_FORALL_NEXT);
  m.attr("OP_SD_PRODUCT") = int(SD_PRODUCT);
  // An evaluation error of Engine.step / Engine.evaluate (the Python evaluator reports it).
  py::register_exception<Engine::StepError>(m, "StepError");
  py::class_<Engine>(m, "Engine")
      .def(py::init<>())
      .def_readwrite("nvars", &Engine::nvars)
      .def("mk_int", [](Engine&, int64_t v) { return Store::mk_int(v, 0); })
      .def("mk_bool", [](Engine&, bool b) { return b ? kTrue : kFalse; })
      .def("mk_str", [](Engine& e, const std::string& s, int64_t rank) { return e.st.mk_str(K_STR, s, rank); })
      .def("mk_model_value", [](Engine& e, const std::string& s, int64_t rank) { return e.st.mk_str(K_MV, s, rank); })
      .def("mk_seq", [](Engine& e, const std::vector<uint32_t>& el) { return e.st.mk_seq(el); })
      // A set or function whose elements or keys TLC cannot compare raises StepError.
      .def("mk_set",
           [](Engine& e, std::vector<uint32_t> el) {
             try {
               return e.st.mk_set(el);
             } catch (const EvalFailure& f) {
               throw Engine::StepError(f.message);
             }
           })
      .def("mk_fun",
           [](Engine& e, const std::vector<uint32_t>& keys, const std::vector<uint32_t>& vals) {
             std::vector<std::pair<uint32_t, uint32_t>> kv;
             for (size_t i = 0; i < keys.size(); ++i) kv.emplace_back(keys[i], vals[i]);
             try {
               return e.st.mk_fun(kv);
             } catch (const EvalFailure& f) {
               throw Engine::StepError(f.message);
             }
           })
      .def("describe", &Engine::describe)
      .def("set_known_ranks",
           [](Engine& e, const std::unordered_map<std::string, int64_t>& r) { e.st.known_ranks = r; })
      // The strings made while checking, in the order made (their ranks follow it).
      .def("made_strings",
           [](Engine& e) {
             std::vector<std::string> out;
             for (uint32_t id : e.st.made_strings) out.push_back(e.st.names[e.st.vals[id].off]);
             return out;
           })
      .def("set_slots", [](Engine& e, size_t n) { e.slots.assign(n, kUnset); })
      .def("build", [](Engine& e, py::handle node) { return reinterpret_cast<uintptr_t>(e.build(node)); })
      .def("configure",
           [](Engine& e, py::handle init, py::handle next, py::list inv, py::list cons, py::list acons, bool deadlock,
              size_t max_mb, py::object progress) {
             e.init = e.build(init);
             e.next = e.build(next);
             for (auto x : inv) e.invariants.push_back(e.build(x));
             for (auto x : cons) e.constraints.push_back(e.build(x));
             for (auto x : acons) e.action_constraints.push_back(e.build(x));
             e.check_deadlock = deadlock;
             e.max_memory_mb = max_mb;
             e.progress = progress;
           })
      .def("step", &Engine::step)
      .def("evaluate", &Engine::evaluate)
      .def("evaluate_all", &Engine::evaluate_all)
      .def("set_view", [](Engine& e, py::handle v) { e.view = e.build(v); })
      .def("run", &Engine::run, py::call_guard<py::gil_scoped_release>())
      .def_readwrite("workers", &Engine::workers)
      .def_readonly("worker_cpu", &Engine::worker_cpu)
      .def_readonly("critical_cpu", &Engine::critical_cpu)
      .def("state", &Engine::state)
      .def_readwrite("record_edges", &Engine::record_edges)
      .def_readwrite("leaf_params", &Engine::leaf_params)
      .def_readonly("initial_count", &Engine::initial_count)
      // Raw native-endian uint32 arrays (Python: array("I", ...)), one copy, no list of ints.
      .def("states_bytes", [](Engine& e) { return as_bytes(e.arena); })
      .def("edges_bytes",
           [](Engine& e) {
             return py::make_tuple(as_bytes(e.edge_src), as_bytes(e.edge_dst), as_bytes(e.edge_leaf),
                                   as_bytes(e.edge_params));
           })
      .def_readwrite("label_vars", &Engine::label_vars)
      .def(
          "labels_bytes",
          [](Engine& e) { return py::make_tuple(as_bytes(e.label_src), as_bytes(e.label_dst), as_bytes(e.label_val)); })
      .def("parent", [](Engine& e, size_t i) { return e.parent[i]; })
      .def("leaf", [](Engine& e, size_t i) { return e.leaf[i]; })
      .def_property_readonly("distinct", &Engine::nstates)
      .def_readonly("generated", &Engine::generated)
      .def_property_readonly("depth", &Engine::max_level)
      .def_readonly("head", &Engine::head)
      .def_readonly("result", &Engine::result)
      .def_readonly("violated", &Engine::violated)
      .def_readonly("trace_to", &Engine::trace_to)
      .def_readonly("extra", &Engine::extra)
      .def_readonly("extra_leaf", &Engine::extra_leaf)
      .def_readonly("initial_violation", &Engine::initial_violation)
      .def_readonly("error", &Engine::error)
      .def_readonly("error_loc", &Engine::error_loc)
      .def_property_readonly("bytes", [](Engine& e) {
        return e.st.bytes() + e.arena.capacity() * 4 + e.parent.capacity() * 4 + e.leaf.capacity() * 4 + seen_bytes(e) +
               e.view_keys.capacity() * 4 +
               (e.edge_src.capacity() + e.edge_dst.capacity() + e.edge_leaf.capacity() + e.edge_params.capacity()) * 4;
      });
}
