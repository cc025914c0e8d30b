// SPDX-License-Identifier: Apache-2.0
#include "safestate/transition_table_export.hpp"

#include <cstddef>
#include <string_view>

#include "safestate/transition_table.hpp"

namespace safestate {

namespace {

void append_json_string(std::string& out, std::string_view s) {
  out += '"';
  for (const char ch : s) {
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      default: out += ch; break;
    }
  }
  out += '"';
}

void append_state_list(std::string& out, StateSet set) {
  out += '[';
  bool first = true;
  for (const StateId s : kAllStates) {
    if (set.contains(s)) {
      if (!first) out += ", ";
      append_json_string(out, to_string(s));
      first = false;
    }
  }
  out += ']';
}

// "RSM-05, INV-RESET" -> ["RSM-05", "INV-RESET"]; "-" -> [].
void append_requirements(std::string& out, std::string_view reqs) {
  out += '[';
  bool first = true;
  while (!reqs.empty()) {
    const std::size_t comma = reqs.find(',');
    std::string_view item = reqs.substr(0, comma);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    if (!item.empty() && item != "-") {
      if (!first) out += ", ";
      append_json_string(out, item);
      first = false;
    }
    if (comma == std::string_view::npos) break;
    reqs.remove_prefix(comma + 1);
  }
  out += ']';
}

void append_field(std::string& out, std::string_view key, std::string_view value) {
  append_json_string(out, key);
  out += ": ";
  append_json_string(out, value);
}

}  // namespace

std::string to_json() {
  std::string out;
  out += "{\"document\": \"docs/design/system-state-manager.md\", \"rows\": [\n";
  for (std::size_t i = 0; i < kTransitionTable.size(); ++i) {
    const TransitionRow& r = kTransitionTable[i];
    out += "  {";
    append_field(out, "id", r.id);
    out += ", ";
    append_field(out, "section", i < kCycleRowCount ? "cycle" : "command");
    out += ", ";
    append_field(out, "event", to_string(r.event));
    out += ", \"source\": ";
    append_state_list(out, r.source);
    out += ", \"effective_source\": ";
    append_state_list(out, effective_source(i));
    out += ", ";
    append_field(out, "guard", r.guard_name);
    out += ", ";
    append_field(out, "kind", to_string(r.kind));
    out += ", \"targets\": ";
    append_state_list(out, r.targets);
    out += ", ";
    append_field(out, "reason", to_string(r.reason));
    out += ", ";
    append_field(out, "stop_category", to_string(r.stop));
    out += ", ";
    append_field(out, "action", r.action_name);
    out += ", \"requirements\": ";
    append_requirements(out, r.requirements);
    out += i + 1 < kTransitionTable.size() ? "},\n" : "}\n";
  }
  out += "]}\n";
  return out;
}

std::string to_dot() {
  std::string out;
  out += "digraph SystemStateManager {\n";
  out += "  rankdir=LR;\n  node [shape=box, style=rounded, fontname=\"Helvetica\"];\n";
  out += "  edge [fontname=\"Helvetica\", fontsize=9];\n";
  for (const StateId s : kAllStates) {
    out += "  ";
    out += to_string(s);
    out += is_powered(s) ? " [penwidth=2];\n" : ";\n";
  }
  std::string rejects;
  for (std::size_t i = 0; i < kTransitionTable.size(); ++i) {
    const TransitionRow& r = kTransitionTable[i];
    std::string label;
    label += r.id;
    label += ' ';
    label += to_string(r.event);
    if (r.guard_name != "always") {
      label += " [";
      label += r.guard_name;
      label += ']';
    }
    if (r.stop != StopUpdate::Keep) {
      label += " / ";
      label += to_string(r.stop);
    }
    if (r.kind == TargetKind::Reject) {
      rejects += label;
      rejects += " -> ";
      rejects += to_string(r.reason);
      rejects += "\\l";
      continue;
    }
    const StateSet from = effective_source(i);
    for (const StateId s : kAllStates) {
      if (!from.contains(s)) continue;
      for (const StateId t : kAllStates) {
        const bool edge = r.kind == TargetKind::Enter ? r.targets.contains(t) : t == s;
        if (!edge) continue;
        out += "  ";
        out += to_string(s);
        out += " -> ";
        out += to_string(t);
        out += " [label=\"";
        out += label;
        out += "\"];\n";
      }
    }
  }
  out += "  REJECTS [shape=note, label=\"Rejected commands (state unchanged)\\l";
  out += rejects;
  out += "\"];\n}\n";
  return out;
}

}  // namespace safestate
