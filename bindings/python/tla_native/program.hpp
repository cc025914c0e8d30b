// SPDX-License-Identifier: Apache-2.0
// The program tree the core evaluates: Init, Next, invariants and constraints arrive
// from Python (python/safestate/checker/native/translate.py) as a tree of tuples
// (op, loc, ints, value id, kids, continuation), built into Nodes (program.cpp) in the
// same order as the Python action compiler's closures, so the successors come in
// TLC's order.  The ops and what each node holds: ops.def.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

namespace safestate::tla_native {

enum Op : int {
#define TLA_OP(name, folds, doc) name,
#include "ops.def"
#undef TLA_OP
  OP_COUNT
};

// Whether a node of the op whose kids are all constants is evaluated when built.
constexpr bool kOpFolds[OP_COUNT] = {
#define TLA_OP(name, folds, doc) folds != 0,
#include "ops.def"
#undef TLA_OP
};

// The ops' names, in order (the module exports them: checker/native/ops.py checks its own).
constexpr const char* kOpNames[OP_COUNT] = {
#define TLA_OP(name, folds, doc) #name,
#include "ops.def"
#undef TLA_OP
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

// Where a node is evaluated: the current state s, the successor t being built (its
// unassigned variables kUnset), null where there is none.
struct Ctx {
  const uint32_t* s = nullptr;
  uint32_t* t = nullptr;
  uint32_t* L = nullptr;
};

}  // namespace safestate::tla_native
