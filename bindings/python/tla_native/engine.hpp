// SPDX-License-Identifier: Apache-2.0
// The engine: one object holds the program tree, the evaluator's scratch and the
// search.  Its members are defined by concern:
//   program.cpp         building the tree from Python's tuples, folding constants
//   eval.cpp            expressions: the dispatch (eval_node), booleans, integers, control
//   eval_sets.cpp       sets: operators, constructors, membership in set descriptors
//   eval_functions.cpp  functions, records, tuples, sequences, EXCEPT
//   print.cpp           values as TLC prints them (ToString)
//   actions.cpp         actions: successors in TLC's order (exec), \A over an action
//   search.cpp          the breadth-first search with one worker: the state set and queue
//   search_inl.hpp      its per-successor path (seen-set, storing, invariants), inline in exec
//   workers.cpp         the search with several workers, level by level
//   step.cpp            one step from a given state (conformance), values for Python
// module.cpp is the Python boundary (the pybind11 module).
#pragma once

#include <pybind11/pybind11.h>
// Every part that converts a value for Python sees the same casters (one definition).
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "program.hpp"
#include "values.hpp"

namespace safestate::tla_native {

namespace py = pybind11;

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
  void clear();
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

  Engine() = default;
  // A worker: a view of the searching engine with its own scratch (slots, buffers).
  Engine(Engine& m, int);

  // ------------------------------------------------------------ building (program.cpp)
  Node* build(py::handle obj);

  // ------------------------------------------------------------ expressions (eval*.cpp)
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
  uint32_t eval_node(Node* n, Ctx& c);

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
  // An operator's arguments, evaluated into its parameters' slots (ints) before the body.
  void bind(Node* n, Ctx& c) {
    for (size_t i = 0; i < n->ints.size(); ++i) {
      uint32_t v = eval(n->kids[i], c);
      slots[size_t(n->ints[i])] = v;
    }
  }

  // eval.cpp: the ops with more than a line (the first five are hot: inline in eval_node,
  // their only caller, as assign and assign_in in exec)
  inline uint32_t primed(Node* n, Ctx& c);
  inline uint32_t let_ref(Node* n, Ctx& c);
  inline uint32_t conjunction(Node* n, Ctx& c);
  inline uint32_t disjunction(Node* n, Ctx& c);
  inline uint32_t divide(Node* n, Ctx& c);
  uint32_t case_of(Node* n, Ctx& c);
  uint32_t quantify(Node* n, Ctx& c);
  uint32_t choose(Node* n, Ctx& c);
  uint32_t call_memo(Node* n, Ctx& c);

  // eval_sets.cpp
  // The largest set SUBSET, \X and [S -> T] enumerate here (beyond: the Python engine).
  static constexpr uint32_t kMaxEnumBits = 20;
  static constexpr uint64_t kMaxEnum = uint64_t(1) << kMaxEnumBits;
  uint32_t range(Node* n, Ctx& c);
  uint32_t in_set(Node* n, Ctx& c);
  uint32_t set_algebra(Node* n, Ctx& c);
  uint32_t subseteq(Node* n, Ctx& c);
  uint32_t set_enum(Node* n, Ctx& c);
  uint32_t set_filter(Node* n, Ctx& c);
  uint32_t set_map(Node* n, Ctx& c);
  uint32_t powerset(Node* n, Ctx& c);
  uint32_t product(Node* n, Ctx& c);
  uint32_t fn_set(Node* n, Ctx& c);
  uint32_t rec_set(Node* n, Ctx& c);
  bool member_sd(uint32_t x, Node* sd, Ctx& c);
  bool items_members(uint32_t x, uint32_t first, uint32_t count, Node* kid, Ctx& c);
  bool not_of_kind(uint32_t x, int loc) const;

  // eval_functions.cpp
  // f[x]: a record's field where it was last time (no call), else apply().
  uint32_t fn_app(Node* n, Ctx& c) {
    uint32_t f = eval(n->kids[0], c);
    uint32_t x = eval(n->kids[1], c);
    if (!Store::is_int(f)) {
      const Val& v = st.vals[f];
      uint32_t h = n->hint.load(std::memory_order_relaxed);
      if (v.kind == K_FUN && h < v.len && v.data[h] == x) return v.data[v.len + h];
    }
    return apply(f, x, n->loc, &n->hint);
  }
  uint32_t apply(uint32_t f, uint32_t x, int loc, std::atomic<uint32_t>* hint = nullptr) const {
    uint32_t i = value_index(f, x, loc, hint);
    return st.items(f)[i];
  }
  uint32_t value_index(uint32_t f, uint32_t x, int loc, std::atomic<uint32_t>* hint) const;
  uint32_t update(uint32_t f, uint32_t x, uint32_t val, int loc);
  uint32_t domain(uint32_t f, int loc);
  uint32_t seq_of(uint32_t v, int loc, const char* what);
  uint32_t except_path(Node* n, Ctx& c, uint32_t f, size_t pos, size_t depth, Node* val, int at_slot);
  uint32_t except_value(Node* n, Ctx& c, uint32_t old, size_t pos, size_t depth, Node* val, int at_slot);
  uint32_t fn_lit(Node* n, Ctx& c);
  uint32_t rec_lit(Node* n, Ctx& c);
  uint32_t tuple(Node* n, Ctx& c);
  uint32_t except(Node* n, Ctx& c);
  uint32_t seq_head(Node* n, Ctx& c);
  uint32_t seq_tail(Node* n, Ctx& c);
  uint32_t seq_append(Node* n, Ctx& c);
  uint32_t seq_concat(Node* n, Ctx& c);
  uint32_t seq_subseq(Node* n, Ctx& c);
  uint32_t select_seq(Node* n, Ctx& c);

  // print.cpp: a value as TLC prints it
  void print(uint32_t v, std::string& out);
  uint32_t to_string(Node* n, Ctx& c);

  // ------------------------------------------------------------ actions (actions.cpp)
  int emit_kind = 0;  // 0: init, 1: next
  void exec(Node* n, Ctx& c);
  // \A x \in S : A in an action (actions.cpp).
  struct Forall {
    std::vector<uint32_t> order;  // the bindings, nb ids each, in the order taken
    size_t pos = 0;
  };
  std::vector<Forall> foralls_;  // per \A (a worker has its own)
  void bind_forall(Node* f, const Forall& fr);
  void forall(Node* n, Ctx& c);
  void forall_next(Node* f, Ctx& c);
  void exists(Node* n, Ctx& c);
  inline void assign(Node* n, Ctx& c);
  inline void assign_in(Node* n, Ctx& c);
  void case_action(Node* n, Ctx& c);
  void all_assigned(Node* n, Ctx& c);

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

  // ------------------------------------------------------------ the search (search.cpp)
  std::vector<uint32_t> arena;  // nvars ids per state: the states and the breadth-first queue
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
  inline int64_t find_or_insert(const uint32_t* x);
  inline int64_t find(const uint32_t* x, uint64_t h) const;
  inline void insert(uint64_t h, uint32_t idx);
  inline void add(const uint32_t* x, int32_t par, int32_t lf, int lvl);
  size_t rss_mb() const;
  std::chrono::steady_clock::time_point last_progress = std::chrono::steady_clock::now();
  void poll_signals();
  void periodic();
  inline bool holds_all(const std::vector<Node*>& preds, Ctx& c, int* which);

  // The state graph (`conform/graph.py`): one edge per successor inside the model, as
  // the Python engine lists them (source, target, action leaf, the leaf's parameters
  // as one interned tuple of their slots' values).  Only the one-worker search records.
  bool record_edges = false;
  std::vector<std::vector<int64_t>> leaf_params;  // per leaf: the slots of its parameters
  std::vector<uint32_t> edge_src, edge_dst, edge_leaf, edge_params;
  size_t initial_count = 0;  // the initial states are the first ones stored
  void record_edge(uint32_t src, uint32_t dst, int lf);

  // The labelled graph of `safestate mutate`'s difference search (mutate/graph.py): per
  // successor inside the model (and per initial state, source 0xFFFFFFFF), the source,
  // the stored target, and the values of `label_vars` in the successor itself as one
  // interned tuple -- under a VIEW the stored target may differ from it outside the
  // VIEW, and the search compares what the step produced.  Only the one-worker search.
  std::vector<int64_t> label_vars;
  std::vector<uint32_t> label_src, label_dst, label_val;
  void record_label(uint32_t src, uint32_t dst, const uint32_t* t);
  // Per action leaf, the label positions (bit q: label_vars[q]) that every step of the
  // leaf copies from its stored source, from the recorded labels and edges (the search's
  // "carried values under a VIEW"); empty when they do not line up or past 64 positions.
  std::vector<uint64_t> copy_masks() const;

  int cur_level = 0;
  uint64_t before = 0;
  inline void on_emit(Ctx& c, int lf);
  void run();

  // ------------------------------------------------------------ several workers (workers.cpp)
  int workers = 1;
  // CPU seconds: each worker's (in levels), and the levels' slowest worker's, summed
  // (the search's critical path, without the serial part: what wall time would be on idle cores).
  std::vector<double> worker_cpu;
  double critical_cpu = 0;
  double level_cpu_ = 0;
  void search_levels();
  void work(Fresh* f);
  inline void offer(Ctx& c, int lf);
  inline bool keep(const uint32_t* x, uint64_t h, const uint32_t* state, uint32_t vk, uint64_t key, int lf);
  void store_level(Fresh& f, std::vector<std::unique_ptr<Engine>>& team);

  // ------------------------------------------------------------ one step from a given state (step.cpp)
  py::object state(size_t i) const;
  py::list step(py::handle action, const std::vector<uint32_t>& state,
                const std::vector<std::pair<int64_t, uint32_t>>& binds);
  uint32_t evaluate(py::handle expr, const std::vector<uint32_t>& state,
                    const std::vector<std::pair<int64_t, uint32_t>>& binds);
  std::vector<uint32_t> evaluate_all(py::list exprs, const std::vector<uint32_t>& state,
                                     const std::vector<std::pair<int64_t, uint32_t>>& binds);
  struct StepError : std::runtime_error {
    using std::runtime_error::runtime_error;
  };
  py::tuple describe(uint32_t id) const;

 private:
  void rank_fields(Node* n);
  void fold(Node* n);
  Node* prepare(py::handle node, const std::vector<uint32_t>& state,
                const std::vector<std::pair<int64_t, uint32_t>>& binds);
  void collect(Ctx& c, int lf, int loc);
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

}  // namespace safestate::tla_native
