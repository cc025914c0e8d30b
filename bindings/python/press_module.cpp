// safestate._press: drives the C++ hydraulic press (chain) and its flat defective reference
// from Python (docs/design/hydraulic-press.md §8). cycle(event) takes one model input event
// ("motor_on", "start", "mode2", ...); observe() returns the models' observables under the
// models' names: motor, mode, step, outputs (a sorted list of output names); the chain
// press adds pressure, speed (the mode parameters driven), active (its active states) and
// log (the entry/exit calls of the last scan, [{kind, state}]).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "safestate/chain/hydraulic_press.hpp"
#include "safestate/chain/press_event.hpp"
#include "safestate/chain/press_flat.hpp"

namespace py = pybind11;
namespace sc = safestate::chain;

namespace {

// One model input event -> one scan's inputs (press_event.hpp); an unknown name is a ValueError.
sc::PressInputs inputs_of(const std::string& e, bool& continuous) {
  const std::optional<sc::PressInputs> i = sc::press_inputs_of(e, continuous);
  if (!i) throw py::value_error("unknown press input event '" + e + "'");
  return *i;
}

py::dict to_dict(const sc::PressObservation& o) {
  std::vector<std::string> outs;
  for (int k = 0; k < static_cast<int>(sc::Output::count_); ++k) {
    if (o.outputs.on(static_cast<sc::Output>(k))) outs.emplace_back(sc::to_string(static_cast<sc::Output>(k)));
  }
  std::sort(outs.begin(), outs.end());
  py::dict d;
  d["motor"] = o.motor;
  d["mode"] = o.mode;
  d["step"] = sc::to_string(o.step);
  d["outputs"] = outs;
  return d;
}

// The chain press's active states, in table (pre-)order: what `safestate demo press` prints.
std::vector<std::string> active_states(const sc::HydraulicPress& p) {
  std::vector<std::string> names;
  for (sc::StateIndex s = 0; s < sc::press::state_count; ++s) {
    if (p.chain().is_active(s)) names.emplace_back(sc::press::table[s].name);
  }
  return names;
}

// The chain's entry/exit calls of the last scan, as the model's log records them.
py::list call_log(const sc::HydraulicPress& p) {
  const auto& calls = p.chain().calls();
  if (calls.overflow()) throw std::runtime_error("the press chain's call log overflowed");
  py::list out;
  for (std::size_t i = 0; i < calls.size(); ++i) {
    py::dict c;
    c["kind"] = sc::to_string(calls[i].kind);
    c["state"] = sc::press::table[calls[i].state].name;
    out.append(c);
  }
  return out;
}

py::dict observe_chain(const sc::HydraulicPress& p) {
  const sc::PressObservation o = p.observe();
  py::dict d = to_dict(o);
  d["pressure"] = o.outputs.pressure_bar;
  d["speed"] = o.outputs.speed_mm_s;
  d["active"] = active_states(p);
  d["log"] = call_log(p);
  return d;
}

py::dict observe_flat(const sc::PressFlat& p) { return to_dict(p.observe()); }

template <class Press, py::dict (*Observe)(const Press&)>
struct Driver {
  Press press;
  bool continuous = false;
  void cycle(const std::string& e) { press.cycle(inputs_of(e, continuous)); }
  py::dict observe() const { return Observe(press); }
  std::vector<std::string> active() const { return active_states(press); }
};
using ChainDriver = Driver<sc::HydraulicPress, &observe_chain>;
using FlatDriver = Driver<sc::PressFlat, &observe_flat>;

}  // namespace

PYBIND11_MODULE(_press, m) {
  m.doc() = "The hydraulic press on the state chain and the flat defective reference (SCH-05)";
  py::class_<ChainDriver>(m, "HydraulicPress")
      .def(py::init<>())
      .def("cycle", &ChainDriver::cycle, py::arg("event"))
      .def("observe", &ChainDriver::observe)
      .def("active", &ChainDriver::active, "the active states, in table order");
  py::class_<FlatDriver>(m, "PressFlat", "DEFECTIVE REFERENCE: reproduces the accident; never a product")
      .def(py::init<>())
      .def("cycle", &FlatDriver::cycle, py::arg("event"))
      .def("observe", &FlatDriver::observe);
}
