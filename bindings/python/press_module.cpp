// safestate._press: drives the C++ hydraulic press (chain) and its flat defective reference
#include <algorithm>
// from Python (docs/design/hydraulic-press.md §7). cycle(event) takes one model input event
// ("motor_on", "start", "mode2", ...); observe() returns the models' observables under the
// models' names: motor, mode, step, outputs (a sorted list of output names).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "safestate/chain/hydraulic_press.hpp"
#include "safestate/chain/press_flat.hpp"

namespace py = pybind11;
namespace sc = safestate::chain;

namespace {

// One model input event -> one scan's inputs; `continuous` is the held level (design §7).
sc::PressInputs inputs_of(const std::string& e, bool& continuous) {
  static const char* const known[] = {"motor_on", "motor_off", "start", "ret", "step_done", "mode1", "mode2",
                                      "mode3", "continuous_on", "continuous_off", "temp_high", "temp_ok"};
  bool ok = false;
  for (const char* k : known) ok = ok || e == k;
  if (!ok) throw py::value_error("unknown press input event '" + e + "'");
  if (e == "continuous_on") continuous = true;
  if (e == "continuous_off") continuous = false;
  sc::PressInputs i;
  i.continuous = continuous;
  i.motor_on = e == "motor_on";
  i.motor_off = e == "motor_off";
  i.start = e == "start";
  i.ret = e == "ret";
  i.step_done = e == "step_done";
  i.temp_high = e == "temp_high";
  i.temp_ok = e == "temp_ok";
  if (e.rfind("mode", 0) == 0) i.mode = static_cast<std::uint8_t>(e.back() - '0');
  return i;
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

}  // namespace

PYBIND11_MODULE(_press, m) {
  m.doc() = "The hydraulic press on the state chain and the flat defective reference (SCH-05)";
  py::class_<Driver<sc::HydraulicPress>>(m, "HydraulicPress")
      .def(py::init<>())
      .def("cycle", &Driver<sc::HydraulicPress>::cycle, py::arg("event"))
      .def("observe", &Driver<sc::HydraulicPress>::observe);
  py::class_<Driver<sc::PressFlat>>(m, "PressFlat", "DEFECTIVE REFERENCE: reproduces the accident; never a product")
      .def(py::init<>())
      .def("cycle", &Driver<sc::PressFlat>::cycle, py::arg("event"))
      .def("observe", &Driver<sc::PressFlat>::observe);
}
