// SPDX-License-Identifier: Apache-2.0
// Run-time export of the transition table for auditors and the conformance suite.
// Allocates (std::string): never call it from the control cycle.
#pragma once

#include <string>

namespace safestate {

/// {"document": ..., "rows": [{"id", "section", "event", "source", "effective_source", "guard",
/// "kind", "targets", "reason", "stop_category", "action", "requirements"}, ...]} in table order.
[[nodiscard]] std::string to_json();

/// Graphviz digraph: one node per leaf state, one edge per (effective source, target) of each
/// Enter row, a self-loop per effective source of each Stay row, and the Reject rows listed
/// in a note node. Every row id appears.
[[nodiscard]] std::string to_dot();

}  // namespace safestate
