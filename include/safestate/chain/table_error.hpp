#pragma once
// Why a state table is not a well-formed chain (docs/design/state-chain.md §1).
#include <cstdint>

namespace safestate::chain {

enum class TableError : std::uint8_t {
  none,
  root_not_first,          // state 0 must be the one root (parent none)
  second_root,             // another state without a parent
  parent_not_before,       // table not in pre-order: a parent after its child
  subtree_not_contiguous,  // table not in pre-order: a subtree interrupted
  bad_initial,             // a sequential non-leaf's initial is not one of its children
  parallel_with_initial,   // a parallel state names an initial child
  parallel_without_children,
  leaf_with_initial,
};

struct TableCheck {
  TableError error = TableError::none;
  unsigned state = 0;  // the offending state's index
  [[nodiscard]] constexpr bool ok() const noexcept { return error == TableError::none; }
};

}  // namespace safestate::chain
