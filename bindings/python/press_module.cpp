// safestate._press: drives the C++ hydraulic press (chain) and its flat defective reference
#include <algorithm>
// from Python (docs/design/hydraulic-press.md §7). cycle(event) takes one model input event
// ("motor_on", "start", "mode2", ...); observe() returns the models' observables under the
// models' names: motor, mode, step, outputs (a sorted list of output names).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
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

template <class Press>
struct Driver {
  Press press;
  bool continuous = false;
  void cycle(const std::string& e) { press.cycle(inputs_of(e, continuous)); }
  py::dict observe() const {
    sc::PressObservation o = press.observe();
    return to_dict(o);
  }
};

// The chain press's active states, in table (pre-)order: what `safestate demo press` prints.
std::vector<std::string> active_states(const Driver<sc::HydraulicPress>& d) {
  std::vector<std::string> names;
  for (sc::StateIndex s = 0; s < sc::press::state_count; ++s) {
    if (d.press.chain().is_active(s)) names.emplace_back(sc::press::table[s].name);
  }
  return names;
}

}  // namespace

PYBIND11_MODULE(_press, m) {
  m.doc() = "The hydraulic press on the state chain and the flat defective reference (SCH-05)";
  py::class_<Driver<sc::HydraulicPress>>(m, "HydraulicPress")
      .def(py::init<>())
      .def("cycle", &Driver<sc::HydraulicPress>::cycle, py::arg("event"))
      .def("observe", &Driver<sc::HydraulicPress>::observe)
      .def("active", &active_states, "the active states, in table order");
  py::class_<Driver<sc::PressFlat>>(m, "PressFlat", "DEFECTIVE REFERENCE: reproduces the accident; never a product")
      .def(py::init<>())
      .def("cycle", &Driver<sc::PressFlat>::cycle, py::arg("event"))
      .def("observe", &Driver<sc::PressFlat>::observe);
}
