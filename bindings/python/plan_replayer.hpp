// SPDX-License-Identifier: Apache-2.0
// The replay of a compact conformance plan (python/safestate/conform/replay_plan.py), shared
// by every binding: the traces are arrays of small ints (the call of each step, the id of
// the model's expected observe line after it), walked here with no Python per step.
//
// A binding supplies the system under test through four callables:
//   make()                      -> a fresh Sut in its initial state (one per trace);
//   apply(Sut&, const Call&, aux_before) -> false when the call's own result disagrees with
//                                   the model (aux_before: the plan's aux of the state before);
//   line(const Sut&, std::string&)  the canonical observe line (same text the adapter builds);
//   rows(const Sut&, std::string&)  the ids of the rows the last step fired, sorted, each
//                                   followed by '|' (compared at the plan's row checks).
#pragma once

#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace safestate_bindings {

namespace py = pybind11;

/// A Python buffer (array.array) of T copied into a vector; the item size must match.
template <typename T>
std::vector<T> buffer_vector(const py::buffer& b, const char* what) {
  const py::buffer_info info = b.request();
  if (info.ndim != 1 || info.itemsize != static_cast<py::ssize_t>(sizeof(T))) {
    throw py::value_error(std::string(what) + ": expected a 1-D buffer of " + std::to_string(sizeof(T)) +
                          "-byte items (array.array)");
  }
  std::vector<T> v(static_cast<std::size_t>(info.shape[0]));
  if (!v.empty()) std::memcpy(v.data(), info.ptr, v.size() * sizeof(T));
  return v;
}

/// The model side of a plan, as ints and canonical lines.
struct PlanArrays {
  std::vector<std::string> lines;         // expected observe lines, by id
  std::vector<std::int8_t> aux;           // per line id: the adapter's aux of that state
  std::vector<std::string> row_lines;     // expected fired-row lines, by id
  std::vector<std::int64_t> starts;       // trace t is steps [starts[t], starts[t+1])
  std::vector<std::int32_t> call_ids;     // per step: index into the binding's call table
  std::vector<std::int32_t> exp_ids;      // per step: expected line id after the step
  std::vector<std::int32_t> initial_ids;  // per trace: the line id of its initial state
  std::vector<std::int64_t> rows_at;      // sorted step indices whose fired rows are compared
  std::vector<std::int32_t> rows_exp;     // per rows_at entry: expected row line id

  PlanArrays(std::vector<std::string> l, const py::buffer& a, std::vector<std::string> rl, const py::buffer& s,
             const py::buffer& c, const py::buffer& e, const py::buffer& i, const py::buffer& ra, const py::buffer& re)
      : lines(std::move(l)),
        aux(buffer_vector<std::int8_t>(a, "aux")),
        row_lines(std::move(rl)),
        starts(buffer_vector<std::int64_t>(s, "starts")),
        call_ids(buffer_vector<std::int32_t>(c, "call_ids")),
        exp_ids(buffer_vector<std::int32_t>(e, "exp_ids")),
        initial_ids(buffer_vector<std::int32_t>(i, "initial_ids")),
        rows_at(buffer_vector<std::int64_t>(ra, "rows_at")),
        rows_exp(buffer_vector<std::int32_t>(re, "rows_exp")) {
    const auto bad = [](const char* what) { throw py::value_error(std::string("replay plan: ") + what); };
    if (starts.empty() || starts.front() != 0 || static_cast<std::size_t>(starts.back()) != call_ids.size()) {
      bad("starts must run from 0 to the number of steps");
    }
    if (exp_ids.size() != call_ids.size()) bad("call_ids and exp_ids differ in length");
    if (initial_ids.size() + 1 != starts.size()) bad("one initial line id per trace");
    if (rows_exp.size() != rows_at.size()) bad("rows_at and rows_exp differ in length");
    if (aux.size() != lines.size()) bad("one aux per line");
    for (const std::int32_t id : exp_ids) {
      if (id < 0 || static_cast<std::size_t>(id) >= lines.size()) bad("a line id is out of range");
    }
    for (const std::int32_t id : initial_ids) {
      if (id < 0 || static_cast<std::size_t>(id) >= lines.size()) bad("an initial line id is out of range");
    }
    for (const std::int32_t id : rows_exp) {
      if (id < 0 || static_cast<std::size_t>(id) >= row_lines.size()) bad("a row line id is out of range");
    }
  }
};

/// Replays traces [first, last) of the plan; (trace, step) of the first disagreement, or
/// (-1, -1).  Every call id must index `calls` (checked).
template <typename Call, typename Make, typename Apply, typename Line, typename Rows>
std::pair<std::int64_t, std::int64_t> run_plan(const PlanArrays& p, const std::vector<Call>& calls, std::int64_t first,
                                               std::int64_t last, Make make, Apply apply, Line line, Rows rows) {
  const auto traces = static_cast<std::int64_t>(p.initial_ids.size());
  if (first < 0 || last > traces || first > last) throw py::value_error("replay plan: trace range out of bounds");
  for (const std::int32_t c : p.call_ids) {
    if (c < 0 || static_cast<std::size_t>(c) >= calls.size())
      throw py::value_error("replay plan: a call id is out of range");
  }
  std::string got;
  std::string fired;
  // The first row check at or after the first step of `first`.
  std::size_t next_row = 0;
  {
    std::size_t lo = 0, hi = p.rows_at.size();
    const std::int64_t from = p.starts[static_cast<std::size_t>(first)];
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (p.rows_at[mid] < from) lo = mid + 1;
      else hi = mid;
    }
    next_row = lo;
  }
  py::gil_scoped_release release;
  for (std::int64_t t = first; t < last; ++t) {
    auto sut = make();
    std::int32_t before = p.initial_ids[static_cast<std::size_t>(t)];
    for (std::int64_t i = p.starts[static_cast<std::size_t>(t)]; i < p.starts[static_cast<std::size_t>(t) + 1]; ++i) {
      const auto k = static_cast<std::size_t>(i);
      bool ok = apply(*sut, calls[static_cast<std::size_t>(p.call_ids[k])], p.aux[static_cast<std::size_t>(before)]);
      line(*sut, got);
      ok = ok && got == p.lines[static_cast<std::size_t>(p.exp_ids[k])];
      if (next_row < p.rows_at.size() && p.rows_at[next_row] == i) {
        rows(*sut, fired);
        ok = ok && fired == p.row_lines[static_cast<std::size_t>(p.rows_exp[next_row])];
        ++next_row;
      }
      if (!ok) return {t, i - p.starts[static_cast<std::size_t>(t)]};
      before = p.exp_ids[k];
    }
  }
  return {-1, -1};
}

/// Sorted row ids, each followed by '|' (the plan's row line of a step); empty ids are
/// rows not fired.
template <std::size_t N>
void row_line(std::array<std::string_view, N> ids, std::string& out) {
  out.clear();
  std::sort(ids.begin(), ids.end());
  for (const std::string_view id : ids) {
    if (id.empty()) continue;
    out.append(id.data(), id.size());
    out.push_back('|');
  }
}

}  // namespace safestate_bindings
