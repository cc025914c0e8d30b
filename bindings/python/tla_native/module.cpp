// SPDX-License-Identifier: Apache-2.0
// safestate._tla_native: the native core of `safestate check` (docs/checker-performance.md,
// "Design of the compiled core"); the Python boundary.  The core's parts: engine.hpp.
#include "engine.hpp"

namespace safestate::tla_native {
namespace {

py::bytes as_bytes(const std::vector<uint32_t>& v) {
  return py::bytes(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(uint32_t));
}

size_t seen_bytes(const Engine& e) {
  size_t n = 0;
  for (auto& sh : e.seen) n += sh.table.capacity() * 4;
  return n;
}

}  // namespace
}  // namespace safestate::tla_native

PYBIND11_MODULE(_tla_native, m) {
  using namespace safestate::tla_native;
  m.doc() = "The native core of safestate check --engine native.";
  // The op table (ops.def): checker/native/ops.py compares its names with these at import.
  m.attr("OP_COUNT") = int(OP_COUNT);
  m.attr("OP_NAMES") = py::tuple(py::cast(std::vector<std::string>(kOpNames, kOpNames + OP_COUNT)));
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
      .def("copy_masks", &Engine::copy_masks)
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
