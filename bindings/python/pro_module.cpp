// SPDX-License-Identifier: Apache-2.0
// safestate._pro: drives the fan controller's C++ (safestate::pro) from Python for the
// conformance adapters (systems/Protection/, systems/RuntimeSupervisor/) and tests.
//  * Protection: ao_safety as an active object (SafetyAo, with sm_protection and the output
//    gate) and ao_diagnostics, one tick per model step; observe() under the names of
//    models/Protection.tla.
//  * Supervisor: RuntimeSupervisor and the dispatch cycle with a test double of the seven
//    units (their reports are the model's environment events); observe() under the names
//    of models/RuntimeSupervisor.tla. PlanReplayer replays conform's compact plan in C++.
//  * Runtime: the whole controller closed around the thermal plant (demo-like scenarios).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "plan_replayer.hpp"
#include "safestate/pro/diagnostics_ao.hpp"
#include "safestate/pro/in_process_comms.hpp"
#include "safestate/pro/protection_row.hpp"
#include "safestate/pro/protection_runtime.hpp"
#include "safestate/pro/runtime_supervisor.hpp"
#include "safestate/pro/safety_ao.hpp"
#include "safestate/pro/thermal_plant.hpp"

namespace py = pybind11;
using namespace safestate::pro;  // NOLINT

namespace {

py::str str(std::string_view s) { return py::str(s.data(), s.size()); }

constexpr std::array<std::string_view, 3> kResults{"OK", "PROTECTION_ENTERED", "LATCH_BLOCKED"};
constexpr std::array<std::string_view, 7> kFaults{"NONE",      "SENSOR_INVALID", "OVER_TEMP",      "UNDER_VOLT",
                                                  "OVER_VOLT", "LATCH_BLOCKED",  "HAZARD_DETECTED"};
constexpr std::array<std::string_view, 5> kSupStates{"INIT", "RUN", "DEGRADED", "SHUTTING_DOWN", "STOPPED"};
constexpr std::array<std::string_view, 4> kUnitStatus{"INIT", "READY", "FAILED", "STOPPED"};
constexpr std::array<std::string_view, kUnitCount> kUnits{"timer",  "dispatcher",  "monitoring", "control",
                                                          "safety", "diagnostics", "comms"};
constexpr std::array<std::string_view, 3> kSafetyInputs{"NONE", "FRESH", "EMPTY"};
constexpr std::array<std::string_view, 5> kAos{"monitoring", "control", "safety", "diagnostics", "comms"};

template <std::size_t N>
std::size_t lookup(const std::array<std::string_view, N>& names, const std::string& s, const char* what) {
  for (std::size_t i = 0; i < N; ++i) {
    if (names[i] == s) return i;
  }
  throw py::value_error(std::string("unknown ") + what + " '" + s + "'");
}

const char* state_name(ProtectionState s) { return s == ProtectionState::protection ? "PROTECTION" : "NORMAL"; }

// A regulated fan command that differs from the safe value, so the gate's choice shows.
constexpr std::uint8_t kRegulatedCommand = 40;

// ao_safety + ao_diagnostics as active objects, one tick per model step.
class ProtectionChain {
 public:
  explicit ProtectionChain(ProtectionLimits limits) : safety_(data_, diagnostics_, limits) {
    (void)diagnostics_.post(AoEvent{AoSignal::start, 0, 0, 0});
    (void)safety_.post(AoEvent{AoSignal::start, 0, 0, 0});
    (void)diagnostics_.run_to_completion();
    (void)safety_.run_to_completion();
    data_.control_command = kRegulatedCommand;
    data_.fan_output = safety_.safety().fan_output(kRegulatedCommand);  // the gate before any tick
    data_.load_enable = safety_.safety().load_enable();
  }

  // One tick: the supervisor's lifecycle event of the previous tick (EVT_DEGRADED /
  // EVT_RECOVERY, delivered to safety and diagnostics before the next tick, as in
  // ProtectionRuntime), monitoring's snapshot, control's command, then safety and
  // diagnostics in dispatch order, each run to completion. Returns the sm_protection row.
  std::string tick(int temp, int volt, bool valid, bool clear, bool hazard_detected, const std::string& lifecycle) {
    if (lifecycle == "DEGRADED" || lifecycle == "RECOVERY") {
      const AoSignal sig = lifecycle == "DEGRADED" ? AoSignal::degraded : AoSignal::recovery;
      deliver(safety_, AoEvent{sig, data_.tick, 0, 0});
      deliver(diagnostics_, AoEvent{sig, data_.tick, 0, 0});
    } else if (lifecycle != "NONE") {
      throw py::value_error("unknown lifecycle event '" + lifecycle + "'");
    }
    ++data_.tick;
    data_.snapshot = SensorSnapshot{static_cast<std::int16_t>(temp), static_cast<std::uint16_t>(volt), valid, clear,
                                    hazard_detected};
    data_.control_command = kRegulatedCommand;
    data_.fan_output = kSafeFanCommandPercent;  // the runtime's fail-safe defaults of a dispatch cycle
    data_.load_enable = false;
    run(safety_);
    run(diagnostics_);
    return std::string(row_id(safety_.safety().last_row()));
  }

  py::dict observe() const {
    const SafetyContext& c = safety_.safety().context();
    py::dict d;
    d["protection_state"] = state_name(c.protection_state);
    d["latch_active"] = c.latch_active;
    d["override_active"] = c.override_active;
    d["fan_cmd"] = data_.fan_output == kSafeFanCommandPercent ? "SAFE" : "REGULATED";
    d["load_enable"] = data_.load_enable;
    d["degraded"] = safety_.safety().degraded();
    d["result"] = str(kResults[static_cast<std::size_t>(data_.safety_result)]);
    d["published"] = state_name(diagnostics_.published_state());
    d["fault_event"] = str(kFaults[static_cast<std::size_t>(safety_.safety().last_fault_event())]);
    return d;
  }
  std::uint32_t lost_events() const { return safety_.unpublished() + diagnostics_.overflow_count(); }

 private:
  void run(ActiveObject& ao) { deliver(ao, AoEvent{AoSignal::tick, data_.tick, 0, 0}); }
  static void deliver(ActiveObject& ao, const AoEvent& e) {
    if (ao.post(e) != PostResult::ok) throw py::value_error("event not posted");
    (void)ao.run_to_completion();
  }

  CycleData data_{};
  DiagnosticsAo diagnostics_{data_};
  SafetyAo safety_;
};

// RuntimeSupervisor and the dispatch cycle with a test double of the seven units: the
// model's environment event of a tick sets the units' reports, then the supervisor's row
// and the dispatch cycle run as in ProtectionRuntime::tick (§7, §8).
class SupervisorDouble {
 public:
  explicit SupervisorDouble(std::uint32_t init_timeout_ticks) : sup_(init_timeout_ticks) {
    in_.status.fill(UnitStatus::init);
  }

  std::string tick(const std::string& kind, const std::string& unit) {
    in_.shutdown_requested = false;
    if (kind == "READY" || kind == "FAIL") {
      in_.status[lookup(kUnits, unit, "unit")] = kind == "READY" ? UnitStatus::ready : UnitStatus::failed;
    } else if (kind == "FATAL_SET" || kind == "FATAL_CLEAR") {
      in_.fatal_fault = kind == "FATAL_SET";
    } else if (kind == "WD_BAD" || kind == "WD_OK") {
      in_.watchdog_ok = kind == "WD_OK";
    } else if (kind == "SHUTDOWN") {
      in_.shutdown_requested = true;
    } else if (kind == "STOPPED") {
      // The unit asked to stop reports it (step 1: control reports the outputs safe).
      const StopStep& target = sup_.stop_target();
      if (target.outputs) {
        in_.outputs_safe_reported = true;
      } else {
        in_.status[index(target.unit)] = UnitStatus::stopped;
      }
    } else if (kind != "NONE") {
      throw py::value_error("unknown event kind '" + kind + "'");
    }
    const SupervisorStep step = sup_.tick(in_);
    const std::array<UnitStatus, kUnitCount> status = in_.status;
    dispatched_ = dispatch_cycle(
        dispatch_gate(step.mode, status[index(UnitId::dispatcher)]),
        [&status](AoId a) { return status[index(unit_of(a))] == UnitStatus::ready; }, [](AoId) {});
    return std::string(step.row->id);
  }

  // observe() as one line, for PlanReplayer: the fields of observe() in a fixed order.
  std::string key() const {
    std::string k(kSupStates[static_cast<std::size_t>(sup_.state())]);
    k += '|';
    for (const UnitStatus s : in_.status) {
      k += kUnitStatus[static_cast<std::size_t>(s)];
      k += ',';
    }
    k += '|' + std::to_string(sup_.init_ticks()) + '|' + std::to_string(sup_.stop_step()) + '|' +
         (sup_.outputs_safe() ? "1" : "0") + '|';
    for (std::size_t i = 0; i < kDispatchOrder.size(); ++i) {
      k += i < dispatched_.count ? kAos[static_cast<std::size_t>(dispatched_.order[i])] : std::string_view("none");
      k += ',';
    }
    k += '|';
    k += kSafetyInputs[static_cast<std::size_t>(safety_input_of(dispatched_))];
    k += '|';
    k += output_stage();
    return k;
  }

  // The runtime's output stage after the tick: the gate is closed at the start of every
  // dispatch cycle and only ao_safety on this tick's snapshot opens it; after shutdown
  // step 1 control's command is the safe value.
  std::string_view output_stage() const {
    return !sup_.outputs_safe() && safety_input_of(dispatched_) == SafetyInput::fresh ? "GATED" : "SAFE";
  }

  py::dict observe() const {
    py::dict d;
    d["sup_state"] = str(kSupStates[static_cast<std::size_t>(sup_.state())]);
    py::dict status;
    for (std::size_t u = 0; u < kUnitCount; ++u)
      status[str(kUnits[u])] = str(kUnitStatus[static_cast<std::size_t>(in_.status[u])]);
    d["status"] = status;
    d["init_ticks"] = sup_.init_ticks();
    d["stop_step"] = sup_.stop_step();
    d["outputs_safe"] = sup_.outputs_safe();
    py::list disp;
    for (std::size_t i = 0; i < kDispatchOrder.size(); ++i) {
      disp.append(i < dispatched_.count ? str(kAos[static_cast<std::size_t>(dispatched_.order[i])]) : py::str("none"));
    }
    d["dispatched"] = disp;
    d["safety_input"] = str(kSafetyInputs[static_cast<std::size_t>(safety_input_of(dispatched_))]);
    d["outputs"] = str(output_stage());
    return d;
  }

 private:
  RuntimeSupervisor sup_;
  SupervisorInputs in_{};
  DispatchRecord dispatched_{};
};

// conform's compact replay plan (plan_replayer.hpp) over fresh doubles: calls are
// (kind, unit); the row a tick fires is compared at the plan's row checks.
struct SupervisorRun {
  SupervisorDouble sut;
  std::string row;
};

class SupervisorPlanReplayer {
 public:
  SupervisorPlanReplayer(std::uint32_t init_timeout_ticks, std::vector<std::pair<std::string, std::string>> calls,
                         safestate_bindings::PlanArrays plan)
      : init_timeout_ticks_(init_timeout_ticks), calls_(std::move(calls)), plan_(std::move(plan)) {}

  std::pair<std::int64_t, std::int64_t> run(std::int64_t first, std::int64_t last) const {
    return safestate_bindings::run_plan(
        plan_, calls_, first, last,
        [this] {
          return std::make_unique<SupervisorRun>(SupervisorRun{SupervisorDouble(init_timeout_ticks_), {}});
        },
        [](SupervisorRun& r, const std::pair<std::string, std::string>& c, std::int8_t) {
          r.row = r.sut.tick(c.first, c.second);
          return true;
        },
        [](const SupervisorRun& r, std::string& k) { k = r.sut.key(); },
        [](const SupervisorRun& r, std::string& k) {
          safestate_bindings::row_line(std::array<std::string_view, 1>{r.row}, k);
        });
  }

 private:
  std::uint32_t init_timeout_ticks_;
  std::vector<std::pair<std::string, std::string>> calls_;
  safestate_bindings::PlanArrays plan_;
};

}  // namespace

PYBIND11_MODULE(_pro, m) {
  m.doc() = "The fan controller's C++ (PRO-01..05): ao_safety, the runtime supervisor, the whole runtime.";
  m.attr("SAFE_FAN_COMMAND") = kSafeFanCommandPercent;
  m.attr("REGULATED_COMMAND") = kRegulatedCommand;

  m.def(
      "transition_table",
      [] {
        py::list rows;
        for (const ProtectionRowSpec& r : kProtectionRows) {
          py::dict d;
          d["id"] = str(r.id);
          rows.append(d);
        }
        return rows;
      },
      "The rows P01..P05 of sm_protection (design §4), for the conformance audit.");

  m.def(
      "supervisor_table",
      [] {
        py::list rows;
        for (const SupervisorRow& r : kSupervisorRows) {
          py::dict d;
          d["id"] = str(r.id);
          rows.append(d);
        }
        return rows;
      },
      "The rows X01..T01 of the supervisor (design §7), for the conformance audit.");

  py::class_<ProtectionChain>(m, "Protection", py::module_local())
      .def(py::init([](int temp_limit, int volt_min, int volt_max) {
             if (volt_min > volt_max) throw py::value_error("volt_min must not exceed volt_max");
             return std::make_unique<ProtectionChain>(ProtectionLimits{static_cast<std::int16_t>(temp_limit),
                                                                       static_cast<std::uint16_t>(volt_min),
                                                                       static_cast<std::uint16_t>(volt_max)});
           }),
           py::arg("temp_limit") = 85, py::arg("volt_min") = 180, py::arg("volt_max") = 300)
      .def("tick", &ProtectionChain::tick, py::arg("temp"), py::arg("volt"), py::arg("valid"), py::arg("clear"),
           py::arg("hazard_detected") = false, py::arg("lifecycle") = "NONE",
           "One tick with this snapshot; returns the sm_protection row that fired.")
      .def("observe", &ProtectionChain::observe)
      .def("lost_events", &ProtectionChain::lost_events);

  py::class_<SupervisorDouble>(m, "Supervisor", py::module_local())
      .def(py::init([](std::uint32_t init_timeout_ticks) {
             if (init_timeout_ticks == 0) throw py::value_error("init_timeout_ticks must be at least 1");
             return SupervisorDouble(init_timeout_ticks);
           }),
           py::arg("init_timeout_ticks") = kInitTimeoutTicks)
      .def("tick", &SupervisorDouble::tick, py::arg("kind"), py::arg("unit") = "none",
           "One tick with this environment event; returns the supervisor row that fired.")
      .def("observe", &SupervisorDouble::observe)
      .def("key", &SupervisorDouble::key)
      .def("copy", [](const SupervisorDouble& s) { return SupervisorDouble(s); });

  py::class_<SupervisorPlanReplayer>(m, "PlanReplayer", py::module_local(),
                                     "conform's compact replay plan walked in C++ (plan_replayer.hpp).")
      .def(py::init([](std::uint32_t init_timeout_ticks, std::vector<std::pair<std::string, std::string>> calls,
                       std::vector<std::string> lines, const py::buffer& aux, std::vector<std::string> row_lines,
                       const py::buffer& starts, const py::buffer& call_ids, const py::buffer& exp_ids,
                       const py::buffer& initial_ids, const py::buffer& rows_at, const py::buffer& rows_exp) {
        return SupervisorPlanReplayer(
            init_timeout_ticks, std::move(calls),
            safestate_bindings::PlanArrays(std::move(lines), aux, std::move(row_lines), starts, call_ids, exp_ids,
                                           initial_ids, rows_at, rows_exp));
      }))
      .def("run", &SupervisorPlanReplayer::run, py::arg("first"), py::arg("last"),
           "Replay traces [first, last): (trace, step in it) of the first disagreement, or (-1, -1).");
}
