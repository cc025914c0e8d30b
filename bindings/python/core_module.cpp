// SPDX-License-Identifier: Apache-2.0
// safestate._core: the Python face of the C++ SystemStateManager. Every name that crosses
// the boundary is the upper-case string of the design page, exactly what the TLA+ model
// and the conformance suite use.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "plan_replayer.hpp"
#include "safestate/command.hpp"
#include "safestate/config.hpp"
#include "safestate/enum_strings.hpp"
#include "safestate/sim/bus_master.hpp"
#include "safestate/speed_monitor.hpp"
#include "safestate/system_state_manager.hpp"
#include "safestate/transition_table.hpp"
#include "safestate/transition_table_export.hpp"

namespace py = pybind11;
using namespace safestate;  // NOLINT

namespace {

py::str str(std::string_view s) { return py::str(s.data(), s.size()); }

template <typename E, std::size_t N>
E parse(const py::handle& value, const std::array<E, N>& all, const char* what) {
  if (!py::isinstance<py::str>(value)) {
    throw py::type_error(std::string(what) + " must be a str, got " + std::string(py::str(py::type::of(value))));
  }
  const auto text = value.cast<std::string>();
  if (const auto e = enum_from_string(text, all)) return *e;
  std::string allowed;
  for (const E e : all) allowed += (allowed.empty() ? "" : ", ") + std::string(to_string(e));
  throw py::value_error(std::string(what) + ": unknown name '" + text + "' (one of " + allowed + ")");
}

JointVector joint_vector(const py::handle& value, const char* what) {
  const auto seq = py::reinterpret_borrow<py::sequence>(value);
  if (!py::isinstance<py::sequence>(value) || py::len(seq) != kAxisCount) {
    throw py::value_error(std::string(what) + " must be a sequence of 6 floats");
  }
  JointVector v{};
  for (std::size_t i = 0; i < kAxisCount; ++i) v[i] = seq[i].cast<double>();
  return v;
}

/// One cycle's inputs as the binding received them. The drives and the bus come either raw
/// (drive_status_words, fieldbus_cycle_counter, working_counter: the process image as is) or
/// as the model's abstract levels (servo_ready, drive_fault, fieldbus_ok), which a simulated
/// EtherCAT master (sim::bus_image) turns into the image the manager's own decoder and
/// watchdog then read, numbering the frame from the manager it is applied to.
struct CycleCall {
  ScanInputs in;
  bool raw_bus{false};
  /// No feedback key given: the contactor and the brakes follow the outputs the manager
  /// wrote last (an ideal device, as `levels` is an ideal bus); given: as read.
  bool contactor_feedback_given{false};
  bool brake_feedback_given{false};
  sim::BusLevels levels{false, false, false};  // a missing key: bus lost, drives not ready
};

ScanOutputs run_cycle(SystemStateManager& m, const CycleCall& c) {
  ScanInputs in = c.in;
  const ScanOutputs last = m.outputs();
  if (!c.contactor_feedback_given) in.contactor_feedback_closed = last.contactor_closed;
  if (!c.brake_feedback_given) in.brake_feedback_released = last.brake_release;
  if (!c.raw_bus) in.bus = sim::bus_image(m.fieldbus_watchdog(), c.levels);
  return m.cycle(in);
}

/// A dict of inputs -> CycleCall. Missing keys keep the zero (safe, tripped) value;
/// unknown keys are an error, so that a misspelt key cannot silently read as "tripped".
CycleCall scan_inputs(const py::dict& d) {
  CycleCall call;
  ScanInputs& in = call.in;
  bool abstract_bus = false;
  for (const auto& item : d) {
    const auto key = item.first.cast<std::string>();
    const py::handle v = item.second;
    if (key == "estop_closed_a") in.estop_closed.a = v.cast<bool>();
    else if (key == "estop_closed_b") in.estop_closed.b = v.cast<bool>();
    else if (key == "safeguard_closed_a") in.safeguard_closed.a = v.cast<bool>();
    else if (key == "safeguard_closed_b") in.safeguard_closed.b = v.cast<bool>();
    else if (key == "enabling_a") in.enabling.a = parse(v, kAllEnablePositions, "enabling_a");
    else if (key == "enabling_b") in.enabling.b = parse(v, kAllEnablePositions, "enabling_b");
    else if (key == "selector_auto") in.selector.auto_ = v.cast<bool>();
    else if (key == "selector_t1") in.selector.t1 = v.cast<bool>();
    else if (key == "selector_t2") in.selector.t2 = v.cast<bool>();
    else if (key == "self_test_ok") in.self_test_ok = v.cast<bool>();
    else if (key == "servo_ready") abstract_bus = true, call.levels.servo_ready = v.cast<bool>();
    else if (key == "drive_fault") abstract_bus = true, call.levels.drive_fault = v.cast<bool>();
    else if (key == "fieldbus_ok") abstract_bus = true, call.levels.fieldbus_ok = v.cast<bool>();
    else if (key == "drive_status_words") {
      const auto seq = v.cast<py::sequence>();
      if (py::len(seq) != kAxisCount) throw py::value_error("drive_status_words must be 6 ints");
      for (std::size_t i = 0; i < kAxisCount; ++i) in.bus.status_words[i] = seq[i].cast<std::uint16_t>();
      call.raw_bus = true;
    } else if (key == "fieldbus_cycle_counter") call.raw_bus = true, in.bus.cycle_counter = v.cast<std::uint16_t>();
    else if (key == "working_counter") call.raw_bus = true, in.bus.working_counter = v.cast<std::uint16_t>();
    else if (key == "operator_link_ok") in.operator_link_ok = v.cast<bool>();
    else if (key == "contactor_feedback_closed") {
      in.contactor_feedback_closed = v.cast<bool>();
      call.contactor_feedback_given = true;
    } else if (key == "brake_feedback_released") {
      in.brake_feedback_released = v.cast<bool>();
      call.brake_feedback_given = true;
    } else if (key == "q") in.q = joint_vector(v, "q");
    else if (key == "qd") in.qd = joint_vector(v, "qd");
    else throw py::key_error("unknown input '" + key + "'");
  }
  if (abstract_bus && call.raw_bus) {
    throw py::value_error(
        "give the drives and bus either raw (drive_status_words, fieldbus_cycle_counter, working_counter) "
        "or as levels (servo_ready, drive_fault, fieldbus_ok), not both");
  }
  return call;
}

py::list axes_list(const ScanOutputs& out) {
  py::list axes;
  for (const AxisState a : out.axes) axes.append(str(to_string(a)));
  return axes;
}

void put_outputs(py::dict& d, const ScanOutputs& out) {
  d["contactor_closed"] = out.contactor_closed;
  d["drive_enable"] = out.drive_enable;
  d["brake_release"] = out.brake_release;
  d["ramp_down_request"] = out.ramp_down_request;
  d["reset_lamp"] = out.reset_lamp;
  d["commanded_speed_mm_s"] = out.commanded_speed_mm_s;
  d["axes"] = axes_list(out);
}

py::dict outputs_dict(const ScanOutputs& out) {
  py::dict d;
  put_outputs(d, out);
  return d;
}

py::dict observe(const SystemStateManager& m) {
  const StatusRecord s = m.status();
  py::dict d;
  d["state"] = str(to_string(s.state));
  d["selector"] = str(to_string(s.selector));
  d["session_mode"] = str(to_string(s.session_mode));
  d["stop_category"] = str(to_string(s.stop_category));
  d["fault_code"] = str(to_string(s.fault_code));
  d["last_reject_reason"] = str(to_string(s.last_reject_reason));
  d["command_result"] = str(to_string(s.command_result));
  d["estop_mismatch"] = s.estop_mismatch;
  d["safeguard_mismatch"] = s.safeguard_mismatch;
  d["enabling_mismatch"] = s.enabling_mismatch;
  d["selector_invalid"] = s.selector_invalid;
  d["state_cycles"] = s.state_cycles;
  d["t2_confirmed"] = s.t2_confirmed;
  d["resume_to"] = str(to_string(s.resume_to));
  d["jog_axis"] = s.jog_axis;
  d["jog_direction"] = s.jog_direction;
  d["jog_speed_mm_s"] = s.jog_speed_mm_s;
  d["queue_length"] = s.queue_length;
  d["stale_commands"] = s.stale_commands;
  d["estop_tested_a"] = s.estop_tested_a;
  d["estop_tested_b"] = s.estop_tested_b;
  d["enable_release_required"] = s.enable_release_required;
  d["contactor_fb_cycles"] = s.contactor_fb_cycles;
  d["brake_fb_cycles"] = s.brake_fb_cycles;
  put_outputs(d, m.outputs());
  return d;
}

py::list state_list(StateSet set) {
  py::list l;
  for (const StateId s : kAllStates) {
    if (set.contains(s)) l.append(str(to_string(s)));
  }
  return l;
}

py::list requirement_list(std::string_view reqs) {
  py::list l;
  while (!reqs.empty()) {
    const std::size_t comma = reqs.find(',');
    std::string_view item = reqs.substr(0, comma);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    if (!item.empty() && item != "-") l.append(str(item));
    if (comma == std::string_view::npos) break;
    reqs.remove_prefix(comma + 1);
  }
  return l;
}

py::list transition_table_list() {
  py::list rows;
  for (std::size_t i = 0; i < kTransitionTable.size(); ++i) {
    const TransitionRow& r = kTransitionTable[i];
    py::dict d;
    d["id"] = str(r.id);
    d["section"] = i < kCycleRowCount ? "cycle" : "command";
    d["event"] = str(to_string(r.event));
    d["source"] = state_list(r.source);
    d["effective_source"] = state_list(effective_source(i));
    d["guard"] = str(r.guard_name);
    d["kind"] = str(to_string(r.kind));
    d["targets"] = state_list(r.targets);
    d["reason"] = str(to_string(r.reason));
    d["stop_category"] = str(to_string(r.stop));
    d["action"] = str(r.action_name);
    d["requirements"] = requirement_list(r.requirements);
    rows.append(d);
  }
  return rows;
}

py::object row_id(const TransitionRow* r) {
  if (r == nullptr) return py::none();
  return str(r->id);
}

py::dict derived_dict(const DerivedInputs& d) {
  py::dict out;
  out["estop_tripped"] = d.estop_tripped;
  out["gate_open"] = d.gate_open;
  out["enable_middle"] = d.enable_middle;
  out["enable_panic"] = d.enable_panic;
  out["selector"] = str(to_string(d.selector));
  out["speed"] = str(to_string(d.speed));
  out["self_test_ok"] = d.self_test_ok;
  out["servo_ready"] = d.servo_ready;
  out["drive_fault"] = d.drive_fault;
  out["fieldbus_ok"] = d.fieldbus_ok;
  out["operator_link_ok"] = d.operator_link_ok;
  out["enable_release_required"] = d.enable_release_required;
  out["discrepancy"] = str(to_string(d.discrepancy));
  return out;
}

template <typename E, std::size_t N>
py::list name_list(const std::array<E, N>& all) {
  py::list l;
  for (const E e : all) l.append(str(to_string(e)));
  return l;
}

py::list dh_to_list(const DhTable& dh) {
  py::list l;
  for (const DhRow& r : dh) l.append(py::make_tuple(r.a_m, r.alpha_rad, r.d_m, r.theta_offset_rad));
  return l;
}

DhTable dh_from(const py::sequence& rows) {
  if (py::len(rows) != kAxisCount) throw py::value_error("dh must have 6 rows (a_m, alpha_rad, d_m, theta_offset_rad)");
  DhTable dh{};
  for (std::size_t i = 0; i < kAxisCount; ++i) {
    const auto row = rows[i].cast<py::sequence>();
    if (py::len(row) != 4) throw py::value_error("each dh row is (a_m, alpha_rad, d_m, theta_offset_rad)");
    dh[i] = DhRow{row[0].cast<double>(), row[1].cast<double>(), row[2].cast<double>(), row[3].cast<double>()};
  }
  return dh;
}

}  // namespace

/// One step of a batch: a cycle's inputs, or a submitted command (kind, axis, direction,
/// speed_mm_s) given as a tuple.
using BatchStep = std::variant<CycleCall, Command>;

std::vector<BatchStep> batch_steps(const py::list& calls) {
  std::vector<BatchStep> steps;
  steps.reserve(calls.size());
  for (const auto& c : calls) {
    if (py::isinstance<py::dict>(c)) {
      steps.emplace_back(scan_inputs(c.cast<py::dict>()));
    } else {
      const auto t = c.cast<py::tuple>();
      if (t.size() != 4) throw py::value_error("a submit step is (kind, axis, direction, speed_mm_s)");
      steps.emplace_back(Command{parse(t[0], kAllCommandKinds, "kind"), t[1].cast<std::int32_t>(),
                                 t[2].cast<std::int32_t>(), t[3].cast<std::int32_t>()});
    }
  }
  return steps;
}

void run_step(SystemStateManager& m, const BatchStep& s) {
  if (const auto* in = std::get_if<CycleCall>(&s)) {
    (void)run_cycle(m, *in);
  } else {
    (void)m.submit(std::get<Command>(s));
  }
}

py::dict rows_dict(const SystemStateManager& m) {
  py::dict d;
  d["cycle"] = row_id(m.last_rows().cycle);
  d["command"] = row_id(m.last_rows().command);
  return d;
}

/// The observable state as one canonical text line, for comparing in bulk without Python
/// objects: observe()'s values in observe()'s key order, each followed by '|'; bools as
/// 1/0, axes joined by ','.  conform's fast replay builds the same line from the model.
void observe_key(const SystemStateManager& m, std::string& k) {
  const StatusRecord s = m.status();
  const ScanOutputs o = m.outputs();
  k.clear();
  const auto add = [&k](std::string_view v) {
    k.append(v.data(), v.size());
    k.push_back('|');
  };
  const auto num = [&k](long long v) {
    k.append(std::to_string(v));
    k.push_back('|');
  };
  add(to_string(s.state));
  add(to_string(s.selector));
  add(to_string(s.session_mode));
  add(to_string(s.stop_category));
  add(to_string(s.fault_code));
  add(to_string(s.last_reject_reason));
  add(to_string(s.command_result));
  num(s.estop_mismatch);
  num(s.safeguard_mismatch);
  num(s.enabling_mismatch);
  num(s.selector_invalid);
  num(s.state_cycles);
  num(s.t2_confirmed ? 1 : 0);
  add(to_string(s.resume_to));
  num(s.jog_axis);
  num(s.jog_direction);
  num(s.jog_speed_mm_s);
  num(static_cast<long long>(s.queue_length));
  num(static_cast<long long>(s.stale_commands));
  num(s.estop_tested_a ? 1 : 0);
  num(s.estop_tested_b ? 1 : 0);
  num(s.enable_release_required ? 1 : 0);
  num(s.contactor_fb_cycles);
  num(s.brake_fb_cycles);
  num(o.contactor_closed ? 1 : 0);
  num(o.drive_enable ? 1 : 0);
  num(o.brake_release ? 1 : 0);
  num(o.ramp_down_request ? 1 : 0);
  num(o.reset_lamp ? 1 : 0);
  num(o.commanded_speed_mm_s);
  for (std::size_t i = 0; i < o.axes.size(); ++i) {
    if (i > 0) k.push_back(',');
    const std::string_view a = to_string(o.axes[i]);
    k.append(a.data(), a.size());
  }
  k.push_back('|');
}

/// The compact-plan replayer of conform (plan_replayer.hpp) over fresh Managers: a cycle's
/// inputs or a submit, whose QUEUE_FULL answer must match the aux (queue full) of the
/// model state before it.
class ManagerPlanReplayer {
 public:
  ManagerPlanReplayer(const Config& config, const py::list& calls, safestate_bindings::PlanArrays plan)
      : config_(config), calls_(batch_steps(calls)), plan_(std::move(plan)) {}

  std::pair<std::int64_t, std::int64_t> run(std::int64_t first, std::int64_t last) const {
    return safestate_bindings::run_plan(
        plan_, calls_, first, last, [this] { return std::make_unique<SystemStateManager>(config_); },
        [](SystemStateManager& m, const BatchStep& s, std::int8_t full_before) {
          if (const auto* in = std::get_if<CycleCall>(&s)) {
            (void)run_cycle(m, *in);
            return true;
          }
          return (m.submit(std::get<Command>(s)) == SubmitResult::queue_full) == (full_before != 0);
        },
        [](const SystemStateManager& m, std::string& k) { observe_key(m, k); },
        [](const SystemStateManager& m, std::string& k) {
          const auto r = m.last_rows();
          safestate_bindings::row_line(std::array<std::string_view, 2>{r.cycle ? r.cycle->id : std::string_view{},
                                                                       r.command ? r.command->id : std::string_view{}},
                                       k);
        });
  }

 private:
  Config config_;
  std::vector<BatchStep> calls_;
  safestate_bindings::PlanArrays plan_;
};

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "The C++ SystemStateManager of safestate (docs/design/system-state-manager.md), for the\n"
      "conformance harness and for scripting. Every state, mode, reason and row is named by the\n"
      "upper-case string of the design page.";

  // module_local: the conformance suite loads a deliberately wrong build of this module
  // (conform/wrong_variant/) beside this one; global registration would clash.
  py::class_<Config>(m, "Config", "Parameters of the manager (design §9). Every field is read/write.",
                     py::module_local())
      .def(py::init<>(), "The defaults of design §9.")
      .def(py::init([](const py::kwargs& kw) {
             Config c;
             py::object self = py::cast(c);
             for (const auto& item : kw) py::setattr(self, item.first, item.second);
             return self.cast<Config>();
           }),
           "Defaults overridden by keyword arguments, e.g. Config(discrepancy_cycles=3).")
      .def_readwrite("cycle_time_us", &Config::cycle_time_us, "Scan cycle period in microseconds (default 1000).")
      .def_readwrite("discrepancy_cycles", &Config::discrepancy_cycles,
                     "D: tolerated cycles of channel disagreement; the D+1-th latches (default 50).")
      .def_readwrite("arming_timeout_cycles", &Config::arming_timeout_cycles,
                     "Cycles ARMING waits for servo_ready after the Servo-on cycle (default 500).")
      .def_readwrite("max_stop_cycles", &Config::max_stop_cycles,
                     "Cycles STOPPING waits for zero speed (default 1000).")
      .def_readwrite("t1_speed_limit_mm_s", &Config::t1_speed_limit_mm_s, "T1 TCP speed limit, mm/s (default 250).")
      .def_readwrite("zero_velocity_rad_s", &Config::zero_velocity_rad_s,
                     "Joint speed at or below which the axis is at rest (default 0.001 rad/s).")
      .def_readwrite("command_queue_limit", &Config::command_queue_limit,
                     "Commands the queue holds, 1..16 (default 8).")
      .def_readwrite("fieldbus_expected_working_counter", &Config::fieldbus_expected_working_counter,
                     "EtherCAT working counter of a complete frame (default 18: 3 per drive).")
      .def_readwrite("fieldbus_lost_cycles_limit", &Config::fieldbus_lost_cycles_limit,
                     "Missed bus cycles in a row tolerated before C24, at most 100 (default 0).")
      .def_readwrite("feedback_allowed_cycles", &Config::feedback_allowed_cycles,
                     "Cycles the contactor and brake feedback may disagree with their command, at most 1000 "
                     "(default 100, C30).")
      .def_readwrite("t2_confirm_timeout_cycles", &Config::t2_confirm_timeout_cycles,
                     "Cycles a T2 confirmation stays valid for a Servo-on (default 30000).")
      .def_readwrite("t2_speed_limit_mm_s", &Config::t2_speed_limit_mm_s,
                     "T2 TCP speed limit, mm/s, above the T1 limit and at most 3000 (default 1000).")
      .def_readwrite("standstill_speed_window_mm_s", &Config::standstill_speed_window_mm_s,
                     "TCP speed the standstill class may admit, below the T1 limit (default 10 mm/s).")
      .def_property(
          "tool_offset_m",
          [](const Config& c) -> py::object {
            if (!c.tool_offset_m) return py::none();
            const auto& t = *c.tool_offset_m;
            return py::make_tuple(t[0], t[1], t[2]);
          },
          [](Config& c, const py::object& v) {
            if (v.is_none()) {
              c.tool_offset_m.reset();
              return;
            }
            const auto seq = v.cast<py::sequence>();
            if (py::len(seq) != 3) throw py::value_error("tool_offset_m is (x, y, z) in metres, or None");
            std::array<double, 3> t{};
            for (std::size_t i = 0; i < 3; ++i) t[i] = seq[i].cast<double>();
            c.tool_offset_m = t;
          },
          "Tool centre point in the flange frame, metres (RSM-10: T1 speed at the tool tip). None (the\n"
          "default) is an invalid Config (TOOL_OFFSET_NOT_GIVEN); (0, 0, 0) states a tool-less flange.")
      .def_property(
          "dh", [](const Config& c) { return dh_to_list(c.dh); },
          [](Config& c, const py::sequence& rows) { c.dh = dh_from(rows); },
          "DH table: 6 tuples (a_m, alpha_rad, d_m, theta_offset_rad); default UR5.")
      .def(
          "validate", [](const Config& c) { return str(to_string(validate(c))); },
          "'NONE' when usable, else the first problem (an invalid Config fails the BOOT self-test).")
      .def("__repr__", [](const Config& c) {
        return "Config(cycle_time_us=" + std::to_string(c.cycle_time_us) +
               ", discrepancy_cycles=" + std::to_string(c.discrepancy_cycles) +
               ", arming_timeout_cycles=" + std::to_string(c.arming_timeout_cycles) +
               ", max_stop_cycles=" + std::to_string(c.max_stop_cycles) +
               ", t1_speed_limit_mm_s=" + std::to_string(c.t1_speed_limit_mm_s) +
               ", t2_speed_limit_mm_s=" + std::to_string(c.t2_speed_limit_mm_s) +
               ", zero_velocity_rad_s=" + std::to_string(c.zero_velocity_rad_s) +
               ", command_queue_limit=" + std::to_string(c.command_queue_limit) + ")";
      });

  py::class_<SystemStateManager>(
      m, "Manager", "One SystemStateManager. A new Manager is a power cycle: it starts in BOOT.", py::module_local())
      .def(py::init<const Config&>(), py::arg("config") = Config{})
      .def(
          "cycle",
          [](SystemStateManager& self, const py::dict& inputs) {
            return outputs_dict(run_cycle(self, scan_inputs(inputs)));
          },
          py::arg("inputs"),
          "Run one scan cycle. `inputs` keys: estop_closed_a/_b, safeguard_closed_a/_b (bool),\n"
          "enabling_a/_b ('RELEASED'|'MIDDLE'|'PANIC'), selector_auto/_t1/_t2, self_test_ok,\n"
          "q, qd (6 floats), and the drives and bus either as levels servo_ready, drive_fault,\n"
          "fieldbus_ok (bool; a simulated EtherCAT master makes the process image) or raw\n"
          "drive_status_words (6 CiA 402 words), fieldbus_cycle_counter, working_counter.\n"
          "A missing key takes its zero, safe value (contacts open, RELEASED, False, 0, bus lost);\n"
          "an unknown key raises KeyError. contactor_feedback_closed and brake_feedback_released\n"
          "(bool, C30): when missing, each follows the output the manager wrote last (an ideal device).\n"
          "Returns the outputs: contactor_closed, drive_enable, brake_release, ramp_down_request,\n"
          "reset_lamp, commanded_speed_mm_s, axes (6 PLCopen state names).")
      .def(
          "submit",
          [](SystemStateManager& self, const py::str& kind, std::int32_t axis, std::int32_t direction,
             std::int32_t speed_mm_s) {
            const CommandKind k = parse(kind, kAllCommandKinds, "kind");
            return str(to_string(self.submit(Command{k, axis, direction, speed_mm_s})));
          },
          py::arg("kind"), py::arg("axis") = 0, py::arg("direction") = 0, py::arg("speed_mm_s") = 0,
          "Queue a command (RESET, SERVO_ON, SERVO_OFF, START, PAUSE, RESUME, JOG_START, JOG_STOP,\n"
          "T2_CONFIRM). Returns 'QUEUED' or 'QUEUE_FULL' (then last_reject_reason is QUEUE_FULL).")
      .def("observe", &observe,
           "The status record and outputs (design §7) as a dict of exactly: state, selector,\n"
           "session_mode, stop_category, fault_code, last_reject_reason, command_result,\n"
           "estop_mismatch, safeguard_mismatch, enabling_mismatch, selector_invalid, state_cycles,\n"
           "t2_confirmed, resume_to, jog_axis, jog_direction, jog_speed_mm_s, queue_length,\n"
           "stale_commands, estop_tested_a, estop_tested_b, enable_release_required,\n"
           "contactor_closed, drive_enable, brake_release, ramp_down_request, reset_lamp,\n"
           "commanded_speed_mm_s, axes.")
      .def(
          "last_rows", [](const SystemStateManager& self) { return rows_dict(self); },
          "Rows fired by the last cycle: {'cycle': 'C17', 'command': 'K12' or None}\n"
          "(cycle is None before the first cycle).")
      .def(
          "derived_inputs", [](const SystemStateManager& self) { return derived_dict(self.derived_inputs()); },
          "The abstract inputs the last cycle derived (design §2): estop_tripped, gate_open,\n"
          "enable_middle, enable_panic, selector, speed, self_test_ok, servo_ready, drive_fault,\n"
          "discrepancy (first discrepancy fault code or 'NONE').")
      .def(
          "drive_status",
          [](const SystemStateManager& self) {
            py::list states;
            py::list warnings;
            for (const DriveStatus& d : self.drive_status().drives) {
              states.append(str(to_string(d.state)));
              warnings.append(d.warning);
            }
            py::dict out;
            out["states"] = states;
            out["warnings"] = warnings;
            out["fieldbus_healthy"] = self.fieldbus_watchdog().healthy();
            out["fieldbus_missed_cycles"] = self.fieldbus_watchdog().missed_cycles();
            return out;
          },
          "What the last cycle decoded (design §2): the CiA 402 state name and warning bit of each\n"
          "drive, and the fieldbus watchdog (healthy, missed cycles in a row).")
      .def_property_readonly(
          "config", [](const SystemStateManager& self) { return self.config(); }, "A copy of the Config.")
      .def_property_readonly(
          "config_error", [](const SystemStateManager& self) { return str(to_string(self.config_error())); },
          "validate() of the Config given at construction.");

  m.def(
      "probe",
      [](const Config& config, const py::list& prefix, const py::list& probes) {
        const std::vector<BatchStep> steps = batch_steps(prefix);
        py::list out;
        for (const auto& p : probes) {
          // A probe is one cycle's inputs, or a list of steps (e.g. a submit, then a cycle).
          const std::vector<BatchStep> tail = py::isinstance<py::list>(p)
                                                  ? batch_steps(p.cast<py::list>())
                                                  : std::vector<BatchStep>{BatchStep(scan_inputs(p.cast<py::dict>()))};
          auto mgr = std::make_unique<SystemStateManager>(config);  // not movable: one per probe
          for (const auto& s : steps) run_step(*mgr, s);
          for (const auto& s : tail) run_step(*mgr, s);
          out.append(py::make_tuple(observe(*mgr), rows_dict(*mgr)));
        }
        return out;
      },
      py::arg("config"), py::arg("prefix"), py::arg("probes"),
      "Input-complete conformance: for each probe (a cycle's inputs dict, or a list of steps), a\n"
      "fresh Manager runs the prefix (cycle inputs dicts and submit tuples (kind, axis, direction,\n"
      "speed_mm_s)), then the probe. Returns [(observe(), last_rows())] per probe.");
  m.def(
      "replay",
      [](const Config& config, const py::list& calls) {
        const std::vector<BatchStep> steps = batch_steps(calls);
        SystemStateManager mgr(config);
        py::list out;
        for (const auto& s : steps) {
          run_step(mgr, s);
          out.append(py::make_tuple(observe(mgr), rows_dict(mgr)));
        }
        return out;
      },
      py::arg("config"), py::arg("calls"),
      "Run the steps (as for probe) on a fresh Manager: [(observe(), last_rows())] after each.");
  m.def(
      "replay_compare",
      [](const Config& config, const py::list& calls, const std::vector<std::int32_t>& steps,
         const std::vector<std::string>& expected, const std::vector<std::int32_t>& expected_ids,
         const std::vector<std::int64_t>& starts, const std::vector<std::int8_t>& submit_full,
         const std::vector<std::int64_t>& rows_at) {
        const std::vector<BatchStep> table = batch_steps(calls);
        py::list rows;
        std::string key;
        std::size_t next_row = 0;
        for (std::size_t t = 0; t + 1 < starts.size(); ++t) {
          auto mgr = std::make_unique<SystemStateManager>(config);
          for (auto i = starts[t]; i < starts[t + 1]; ++i) {
            const BatchStep& s = table.at(static_cast<std::size_t>(steps.at(static_cast<std::size_t>(i))));
            bool ok = true;
            if (const auto* in = std::get_if<CycleCall>(&s)) {
              (void)run_cycle(*mgr, *in);
            } else {
              const bool full = mgr->submit(std::get<Command>(s)) == SubmitResult::queue_full;
              ok = full == (submit_full.at(static_cast<std::size_t>(i)) != 0);
            }
            observe_key(*mgr, key);
            ok = ok && key == expected.at(static_cast<std::size_t>(expected_ids.at(static_cast<std::size_t>(i))));
            if (next_row < rows_at.size() && rows_at[next_row] == i) {
              rows.append(py::make_tuple(row_id(mgr->last_rows().cycle), row_id(mgr->last_rows().command)));
              ++next_row;
            }
            if (!ok) return py::tuple(py::make_tuple(static_cast<std::int64_t>(t), static_cast<std::int64_t>(i), rows));
          }
        }
        return py::tuple(py::make_tuple(std::int64_t{-1}, std::int64_t{-1}, rows));
      },
      py::arg("config"), py::arg("calls"), py::arg("steps"), py::arg("expected"), py::arg("expected_ids"),
      py::arg("starts"), py::arg("submit_full"), py::arg("rows_at"),
      "Fast trace replay, compared in C++: traces t run steps[starts[t]:starts[t+1]] (indices into\n"
      "calls, as for probe) each on a fresh Manager; after step i the observe_key line must equal\n"
      "expected[expected_ids[i]] and a submit must answer QUEUE_FULL exactly when submit_full[i].\n"
      "Returns (trace, step) of the first disagreement or (-1, -1), and (cycle row, command row)\n"
      "after each step listed in rows_at (sorted).");
  py::class_<ManagerPlanReplayer>(m, "PlanReplayer", py::module_local(),
                                  "conform's compact replay plan (python/safestate/conform/replay_plan.py)\n"
                                  "walked in C++: one fresh Manager per trace, no Python per step.")
      .def(py::init([](const Config& config, const py::list& calls, std::vector<std::string> lines,
                       const py::buffer& aux, std::vector<std::string> row_lines, const py::buffer& starts,
                       const py::buffer& call_ids, const py::buffer& exp_ids, const py::buffer& initial_ids,
                       const py::buffer& rows_at, const py::buffer& rows_exp) {
             return ManagerPlanReplayer(
                 config, calls,
                 safestate_bindings::PlanArrays(std::move(lines), aux, std::move(row_lines), starts, call_ids, exp_ids,
                                                initial_ids, rows_at, rows_exp));
           }),
           py::arg("config"), py::arg("calls"), py::arg("lines"), py::arg("aux"), py::arg("row_lines"),
           py::arg("starts"), py::arg("call_ids"), py::arg("exp_ids"), py::arg("initial_ids"), py::arg("rows_at"),
           py::arg("rows_exp"),
           "calls as for probe (cycle inputs dicts, submit tuples); lines: the expected observe_key lines;\n"
           "aux[line]: 1 when that state's queue is full (a submit from it must answer QUEUE_FULL);\n"
           "row_lines: expected fired rows ('C17|K12|'); the rest are array.array buffers (see the header).")
      .def("run", &ManagerPlanReplayer::run, py::arg("first"), py::arg("last"),
           "Replay traces [first, last): (trace, step in it) of the first disagreement, or (-1, -1).");
  m.def(
      "observe_key",
      [](const SystemStateManager& self) {
        std::string k;
        observe_key(self, k);
        return k;
      },
      "The canonical observable line that replay_compare compares (see there).");
  m.def("transition_table", &transition_table_list,
        "The transition table, rows C01..C23 then K01..K35, as dicts: id, section, event, source,\n"
        "effective_source, guard, kind (ENTER|STAY|REJECT), targets, reason, stop_category,\n"
        "action, requirements.");
  m.def("transition_table_json", &to_json, "The transition table as JSON text.");
  m.def("transition_table_dot", &to_dot, "The transition table as a Graphviz digraph.");
  m.def(
      "tcp_speed_mm_s",
      [](const py::sequence& q, const py::sequence& qd, const Config& config) {
        return SpeedMonitor(config).tcp_speed_mm_s(joint_vector(q, "q"), joint_vector(qd, "qd"));
      },
      py::arg("q"), py::arg("qd"), py::arg("config") = Config{},
      "Linear TCP speed |J_v(q)·qd| in mm/s (q in rad, qd in rad/s) with the Config's DH table.");
  m.def(
      "speed_level",
      [](const py::sequence& q, const py::sequence& qd, const Config& config) {
        return str(to_string(SpeedMonitor(config).classify(joint_vector(q, "q"), joint_vector(qd, "qd"))));
      },
      py::arg("q"), py::arg("qd"), py::arg("config") = Config{},
      "The design §2 speed level of (q, qd): 'ZERO', 'MOVING', 'OVER_T1' or 'OVER_T2'.");
  m.def(
      "names",
      [] {
        py::dict d;
        d["state"] = name_list(kAllStates);
        d["selector"] = name_list(kAllSelectorReadings);
        d["session_mode"] = name_list(kAllOperatingModes);
        d["stop_category"] = name_list(kAllStopCategories);
        d["fault_code"] = name_list(kAllFaultCodes);
        d["reject_reason"] = name_list(kAllRejectReasons);
        d["command"] = name_list(kAllCommandKinds);
        d["enabling"] = name_list(kAllEnablePositions);
        d["speed_level"] = name_list(kAllSpeedLevels);
        d["resume_to"] = name_list(kAllResumeTargets);
        d["axis_state"] = name_list(kAllAxisStates);
        return d;
      },
      "Every enum's names, by field.");
  m.attr("AXIS_COUNT") = kAxisCount;
  m.attr("MAX_QUEUE_CAPACITY") = kMaxQueueCapacity;
}
