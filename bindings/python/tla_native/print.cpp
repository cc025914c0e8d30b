// SPDX-License-Identifier: Apache-2.0
// Values as TLC prints them (values.fmt), for ToString.
#include "engine.hpp"

namespace safestate::tla_native {

// A function of strings as a record, another function as (k :> v @@ ...); a set's
// elements and a function's keys are in TLC's order already.
void Engine::print(uint32_t v, std::string& out) {
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

uint32_t Engine::to_string(Node* n, Ctx& c) {
  std::string out;
  print(eval(n->kids[0], c), out);
  return st.made_str(out);
}

}  // namespace safestate::tla_native
