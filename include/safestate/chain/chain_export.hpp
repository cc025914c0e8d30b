#pragma once
// Export of a chain's tree as JSON and Graphviz DOT (docs, not the control cycle).
#include <cstddef>
#include <string>

#include "safestate/chain/state_chain.hpp"

namespace safestate::chain {

template <class Ctx, std::size_t N>
[[nodiscard]] std::string to_json(const StateTable<Ctx, N>& t) {
  std::string out = "{\"states\": [";
  for (std::size_t s = 0; s < N; ++s) {
    if (s != 0) out += ", ";
    out += "{\"name\": \"" + std::string(t[s].name) + "\", \"parent\": ";
    out += t[s].parent == no_state ? std::string("null") : "\"" + std::string(t[t[s].parent].name) + "\"";
    out += ", \"initial\": ";
    out += t[s].initial == no_state ? std::string("null") : "\"" + std::string(t[t[s].initial].name) + "\"";
    out += std::string(", \"parallel\": ") + (t[s].parallel ? "true" : "false") + "}";
  }
  return out + "]}";
}

// Solid edges: parent -> child; bold: the initial child; doubled box: a parallel state.
template <class Ctx, std::size_t N>
[[nodiscard]] std::string to_dot(const StateTable<Ctx, N>& t) {
  std::string out = "digraph chain {\n  node [shape=box];\n";
  for (std::size_t s = 0; s < N; ++s) {
    out += "  \"" + std::string(t[s].name) + "\"" + (t[s].parallel ? " [peripheries=2]" : "") + ";\n";
  }
  for (std::size_t s = 1; s < N; ++s) {
    const StateIndex p = t[s].parent;
    out += "  \"" + std::string(t[p].name) + "\" -> \"" + std::string(t[s].name) + "\"" +
           (t[p].initial == s ? " [style=bold]" : "") + ";\n";
  }
  return out + "}\n";
}

}  // namespace safestate::chain
