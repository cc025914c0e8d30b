// SPDX-License-Identifier: Apache-2.0
// safestate._saf: drives the C++ Safety service (safestate::saf) from Python, for the
// conformance adapter (docs/design/safety-service.md §12). observe() returns the model's
// variables under the model's names with the model's string values.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "plan_replayer.hpp"
#include "safestate/saf/safety_service.hpp"
#include "safestate/saf/transition_table.hpp"

namespace py = pybind11;
using namespace safestate::saf;  // NOLINT

namespace {

/// The authority code of a SafetyService built from the model's constants (design §12).
constexpr std::uint8_t kAuthorityCode = 225;

/// Report Control holder used for the model's control = "OTHER" (design §12).
constexpr std::uint32_t kOtherComponentId = 0x0009'0909;

py::str str(std::string_view s) { return py::str(s.data(), s.size()); }

py::bytes to_bytes(const Encoded& e) { return py::bytes(reinterpret_cast<const char*>(e.bytes.data()), e.size); }

std::string field(const py::dict& inbox, const char* key) {
  if (!inbox.contains(key)) throw py::key_error(std::string("inbox has no field '") + key + "'");
  const py::handle v = inbox[key];
  if (!py::isinstance<py::str>(v)) throw py::type_error(std::string("inbox.") + key + " must be a str");
  return v.cast<std::string>();
}

[[noreturn]] void bad(const char* key, const std::string& value, const char* allowed) {
  throw py::value_error(std::string("inbox.") + key + ": unknown value '" + value + "' (one of " + allowed + ")");
}

/// One datagram with the transport's intake verdict (design §5).
struct Tagged {
  Encoded bytes;
  Sender from;
  bool fresh;
};

/// The model's inbox record -> the datagrams of one cycle, in the order of design §12: a
/// genuine value comes from the peer of its kind, fresh; "_SPOOFED" from another source;
/// "_REPLAYED" from the Safety Client with a sequence number outside the replay window.
std::vector<Tagged> encode_inbox(const py::dict& inbox) {
  std::vector<Tagged> out;
  const std::string estop = field(inbox, "estop");
  if (estop == "SET" || estop == "CLEAR")
    out.push_back({encode(Message::set_estop(estop == "SET")), Sender::Client, true});
  else if (estop == "CLEAR_SPOOFED") out.push_back({encode(Message::set_estop(false)), Sender::Other, true});
  else if (estop == "CLEAR_REPLAYED") out.push_back({encode(Message::set_estop(false)), Sender::Client, false});
  else if (estop != "NONE") bad("estop", estop, "NONE, CLEAR, SET, CLEAR_SPOOFED, CLEAR_REPLAYED");
  const std::string health = field(inbox, "health");
  const auto report = [&out](Health h, Sender from) { out.push_back({encode(Message::report_health(h)), from, true}); };
  if (health == "NORMAL") report(Health::Normal, Sender::Subsystem);
  else if (health == "WARNING") report(Health::Warning, Sender::Subsystem);
  else if (health == "ERROR") report(Health::Error, Sender::Subsystem);
  else if (health == "FATAL") report(Health::Fatal, Sender::Subsystem);
  else if (health == "NORMAL_SPOOFED") report(Health::Normal, Sender::Other);
  else if (health != "NONE") bad("health", health, "NONE, NORMAL, WARNING, ERROR, FATAL, NORMAL_SPOOFED");
  const std::string control = field(inbox, "control");
  const auto accepted = encode(Message::confirm_control(ControlResponse::Accepted));
  const auto us = encode(Message::report_control(kSafetyComponentId, kAuthorityCode));
  if (control == "ACCEPTED") out.push_back({accepted, Sender::Subsystem, true});
  else if (control == "REFUSED")
    out.push_back({encode(Message::confirm_control(ControlResponse::NotAvailable)), Sender::Subsystem, true});
  else if (control == "US") out.push_back({us, Sender::Subsystem, true});
  else if (control == "OTHER")
    out.push_back({encode(Message::report_control(kOtherComponentId, 255)), Sender::Subsystem, true});
  else if (control == "ACCEPTED_SPOOFED") out.push_back({accepted, Sender::Other, true});
  else if (control == "US_SPOOFED") out.push_back({us, Sender::Other, true});
  else if (control != "NONE")
    bad("control", control, "NONE, ACCEPTED, REFUSED, US, OTHER, ACCEPTED_SPOOFED, US_SPOOFED");
  const std::string subsys = inbox.contains("subsys") ? field(inbox, "subsys") : std::string("NONE");
  if (subsys == "OPERATIONAL") {
    out.push_back({encode(Message::report_subsystem_state(SubsystemState::Operational)), Sender::Subsystem, true});
  } else if (subsys != "NONE") {
    bad("subsys", subsys, "NONE, OPERATIONAL");
  }
  return out;
}

const char* peer_name(Sender p) {
  switch (p) {
    case Sender::Client: return "CLIENT";
    case Sender::Subsystem: return "SUBSYSTEM";
    case Sender::Other: return "OTHER";
  }
  return "OTHER";
}

Sender peer_of_name(const std::string& s) {
  if (s == "CLIENT") return Sender::Client;
  if (s == "SUBSYSTEM") return Sender::Subsystem;
  if (s == "OTHER") return Sender::Other;
  throw py::value_error("peer: unknown value '" + s + "' (one of CLIENT, SUBSYSTEM, OTHER)");
}

/// The peer a datagram of this kind comes from when the caller does not say (a perfectly
/// bound transport); undecodable bytes count as from another source.
Sender default_peer(const std::string& d) {
  const DecodeResult r = decode(reinterpret_cast<const std::uint8_t*>(d.data()), d.size());
  if (!r.ok()) return Sender::Other;
  return r.message.id == MessageId::SetEstop ? Sender::Client : Sender::Subsystem;
}

/// A datagram as conform's plan carries it: bytes, peer (0 client, 1 subsystem, 2 other), fresh.
using PlanDatagram = std::tuple<std::string, int, bool>;

void push_tagged(InboundBatch& batch, const std::string& d, Sender from, bool fresh) {
  (void)batch.push(reinterpret_cast<const std::uint8_t*>(d.data()), d.size(), from, fresh);
}

py::dict observe(const SafetyService& s) {
  const Observable& o = s.observe();
  py::dict d;
  d["state"] = str(to_string(o.state));
  d["estop"] = str(to_string(o.estop));
  d["estop_age"] = o.estop_age;
  d["health"] = str(to_string(o.health));
  d["health_age"] = o.health_age;
  d["control"] = str(to_string(o.control));
  d["control_age"] = o.control_age;
  d["out_request"] = str(to_string(o.out_request));
  d["out_set_state"] = str(to_string(o.out_set_state));
  d["alarm"] = o.alarm;
  d["resend"] = o.resend;
  d["set_age"] = o.set_age;
  return d;
}

py::dict result_dict(const CycleResult& r) {
  py::dict d;
  d["state_row"] = str(r.state_row);
  d["control_row"] = str(r.control_row);
  py::list out;
  for (std::size_t i = 0; i < r.outbox.count; ++i) out.append(to_bytes(encode(r.outbox.messages[i])));
  d["outbox"] = out;
  return d;
}

/// Each datagram is bytes (tagged as from the peer of its kind, fresh) or a tuple
/// (bytes, peer name, fresh): the transport's intake verdict (design §5).
CycleResult cycle_raw(SafetyService& s, const py::list& datagrams, bool hardware_fault) {
  if (datagrams.size() > kMaxInboundPerCycle) {
    throw py::value_error("at most " + std::to_string(kMaxInboundPerCycle) + " datagrams per cycle");
  }
  InboundBatch batch{};
  for (const py::handle h : datagrams) {
    if (py::isinstance<py::bytes>(h)) {
      const std::string d = h.cast<std::string>();
      push_tagged(batch, d, default_peer(d), true);
    } else {
      const auto [d, peer, fresh] = h.cast<std::tuple<py::bytes, std::string, bool>>();
      push_tagged(batch, std::string(d), peer_of_name(peer), fresh);
    }
  }
  return s.cycle(batch, hardware_fault);
}

/// observe() as one line for PlanReplayer: its values in its key order, each followed by '|'.
void observe_line(const SafetyService& s, std::string& k) {
  const Observable& o = s.observe();
  k.clear();
  const auto add = [&k](std::string_view v) {
    k.append(v.data(), v.size());
    k.push_back('|');
  };
  add(to_string(o.state));
  add(to_string(o.estop));
  add(std::to_string(o.estop_age));
  add(to_string(o.health));
  add(std::to_string(o.health_age));
  add(to_string(o.control));
  add(std::to_string(o.control_age));
  add(to_string(o.out_request));
  add(to_string(o.out_set_state));
  add(o.alarm ? "True" : "False");
  add(o.resend ? "True" : "False");
  add(std::to_string(o.set_age));
}

/// One step of a plan: the inbox's datagrams (with their intake verdicts) and the hardware
/// fault line.
using SafCall = std::pair<std::vector<PlanDatagram>, bool>;

struct SafRun {
  SafetyService svc;
  std::size_t steps;
  CycleResult last;
};

/// conform's compact replay plan (plan_replayer.hpp) on the codec path, as the adapter's
/// apply(): step k of a trace also carries garbage[k % garbage.size()], inserted at
/// position k % (datagrams + 1) among the valid ones (which must change nothing).
class SafPlanReplayer {
 public:
  SafPlanReplayer(Timing timing, std::vector<std::string> garbage, std::vector<SafCall> calls,
                  safestate_bindings::PlanArrays plan)
      : timing_(timing), garbage_(std::move(garbage)), calls_(std::move(calls)), plan_(std::move(plan)) {
    if (garbage_.empty()) throw py::value_error("PlanReplayer: at least one garbage datagram");
    for (const SafCall& c : calls_) {
      if (c.first.size() + 1 > kMaxInboundPerCycle) throw py::value_error("PlanReplayer: too many datagrams in a call");
    }
  }

  std::pair<std::int64_t, std::int64_t> run(std::int64_t first, std::int64_t last) const {
    return safestate_bindings::run_plan(
        plan_, calls_, first, last,
        [this] {
          return std::make_unique<SafRun>(SafRun{SafetyService(timing_, kAuthorityCode), 0, {}});
        },
        [this](SafRun& r, const SafCall& c, std::int8_t) {
          const std::string& garbage = garbage_[r.steps % garbage_.size()];
          const std::size_t at = r.steps % (c.first.size() + 1);
          ++r.steps;
          InboundBatch batch{};
          for (std::size_t i = 0; i <= c.first.size(); ++i) {
            if (i == at) push_tagged(batch, garbage, Sender::Other, true);
            if (i < c.first.size()) {
              const auto& [d, peer, fresh] = c.first[i];
              push_tagged(batch, d, static_cast<Sender>(peer), fresh);
            }
          }
          r.last = r.svc.cycle(batch, c.second);
          return true;
        },
        [](const SafRun& r, std::string& k) { observe_line(r.svc, k); },
        [](const SafRun& r, std::string& k) {
          safestate_bindings::row_line(std::array<std::string_view, 2>{r.last.state_row, r.last.control_row}, k);
        });
  }

 private:
  Timing timing_;
  std::vector<std::string> garbage_;
  std::vector<SafCall> calls_;
  safestate_bindings::PlanArrays plan_;
};

}  // namespace

PYBIND11_MODULE(_saf, m) {
  m.doc() = "The C++ Safety service (SAF-01..04), driven one scan cycle at a time.";
  m.attr("MAX_INBOUND_PER_CYCLE") = kMaxInboundPerCycle;
  m.attr("COMPONENT_ID") = kSafetyComponentId;

  m.def(
      "encode_inbox",
      [](const py::dict& inbox) {
        py::list out;
        for (const Tagged& e : encode_inbox(inbox))
          out.append(py::make_tuple(to_bytes(e.bytes), peer_name(e.from), e.fresh));
        return out;
      },
      py::arg("inbox"), "The datagrams of one model inbox (design §12), encoded: [(bytes, peer, fresh)].");

  m.def(
      "transition_table",
      [] {
        py::list rows;
        auto add = [&rows](std::string_view id, const char* table) {
          py::dict d;
          d["id"] = str(id);
          d["table"] = table;
          rows.append(d);
        };
        for (const StateRow& r : kStateRows) add(r.id, "state");
        for (const ControlRow& r : kControlRows) add(r.id, "control");
        return rows;
      },
      "Every row of design §6 (state) and §7 (control): [{id, table}], for the conformance audit.");

  m.def(
      "decode_error",
      [](const py::bytes& b) {
        const std::string_view v = b;
        return str(to_string(decode(reinterpret_cast<const std::uint8_t*>(v.data()), v.size()).error));
      },
      py::arg("datagram"), "NONE for a well-formed datagram, else the reject reason.");

  // module_local: the wrong-variant build (conform/wrong_variant/) loads a second module
  // with the same C++ type into the same process.
  py::class_<SafPlanReplayer>(m, "PlanReplayer", py::module_local(),
                              "conform's compact replay plan walked in C++ (plan_replayer.hpp), on the codec path.")
      .def(py::init([](const std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>& timing,
                       std::vector<std::string> garbage, std::vector<SafCall> calls, std::vector<std::string> lines,
                       const py::buffer& aux, std::vector<std::string> row_lines, const py::buffer& starts,
                       const py::buffer& call_ids, const py::buffer& exp_ids, const py::buffer& initial_ids,
                       const py::buffer& rows_at, const py::buffer& rows_exp) {
             const auto [estop, report, interval, check] = timing;
             if (estop == 0 || report == 0 || interval == 0 || check == 0) {
               throw py::value_error("every timer must be at least 1 cycle");
             }
             return SafPlanReplayer(Timing{estop, report, interval, check}, std::move(garbage), std::move(calls),
                                    safestate_bindings::PlanArrays(std::move(lines), aux, std::move(row_lines), starts,
                                                                   call_ids, exp_ids, initial_ids, rows_at, rows_exp));
           }),
           py::arg("timing"), py::arg("garbage"), py::arg("calls"), py::arg("lines"), py::arg("aux"),
           py::arg("row_lines"), py::arg("starts"), py::arg("call_ids"), py::arg("exp_ids"), py::arg("initial_ids"),
           py::arg("rows_at"), py::arg("rows_exp"),
           "timing: (estop, report data, message interval, check interval) cycles; garbage: one\n"
           "datagram per step in turn; calls: (datagrams, hardware fault) per call id.")
      .def("run", &SafPlanReplayer::run, py::arg("first"), py::arg("last"),
           "Replay traces [first, last): (trace, step in it) of the first disagreement, or (-1, -1).");
  m.def(
      "observe_line",
      [](const SafetyService& s) {
        std::string k;
        observe_line(s, k);
        return k;
      },
      "The canonical observe line PlanReplayer compares.");

  py::class_<SafetyService>(m, "SafetyService", py::module_local())
      .def(py::init([](std::uint32_t estop_timeout_cycles, std::uint32_t report_data_timeout_cycles,
                       std::uint32_t message_interval_cycles, std::uint32_t check_interval_cycles,
                       std::uint8_t authority_code) {
             if (estop_timeout_cycles == 0 || report_data_timeout_cycles == 0 || message_interval_cycles == 0 ||
                 check_interval_cycles == 0) {
               throw py::value_error("every timer must be at least 1 cycle");
             }
             return SafetyService(Timing{estop_timeout_cycles, report_data_timeout_cycles, message_interval_cycles,
                                         check_interval_cycles},
                                  authority_code);
           }),
           py::arg("estop_timeout_cycles"), py::arg("report_data_timeout_cycles"), py::arg("message_interval_cycles"),
           py::arg("check_interval_cycles") = 20, py::arg("authority_code") = kAuthorityCode)
      .def(
          "cycle",
          [](SafetyService& s, const py::dict& inbox) {
            const std::vector<Tagged> encoded = encode_inbox(inbox);
            InboundBatch batch{};
            for (const Tagged& e : encoded) (void)batch.push(e.bytes, e.from, e.fresh);
            const py::handle hw = inbox.contains("hw_fault") ? inbox["hw_fault"] : py::handle(Py_False);
            if (!py::isinstance<py::bool_>(hw)) throw py::type_error("inbox.hw_fault must be a bool");
            return result_dict(s.cycle(batch, hw.cast<bool>()));
          },
          py::arg("inbox"), "One cycle with the model's inbox record (encoded per design §12).")
      .def(
          "cycle_raw",
          [](SafetyService& s, const py::list& datagrams, bool hardware_fault) {
            return result_dict(cycle_raw(s, datagrams, hardware_fault));
          },
          py::arg("datagrams"), py::arg("hardware_fault") = false,
          "One cycle with raw datagrams (the codec path; garbage allowed): each bytes (from the peer of\n"
          "its kind, fresh) or (bytes, 'CLIENT'|'SUBSYSTEM'|'OTHER', fresh).")
      .def(
          "copy", [](const SafetyService& s) { return SafetyService(s); },
          "An independent copy (the service is plain data): replay branches from one state.")
      .def("observe", &observe, "The model's variables: state, estop, estop_age, ...")
      .def("diagnostics", [](const SafetyService& s) {
        const Diagnostics& d = s.diagnostics();
        py::dict out;
        out["cycles"] = d.cycles;
        out["accepted"] = d.accepted;
        py::dict rej;
        for (std::size_t i = 1; i < kDecodeErrorCount; ++i) {
          rej[str(to_string(static_cast<DecodeError>(i)))] = d.rejected[i];
        }
        out["rejected"] = rej;
        out["rejected_source"] = d.rejected_source;
        out["rejected_stale"] = d.rejected_stale;
        out["unsolicited_confirm"] = d.unsolicited_confirm;
        out["inconsistent_report"] = d.inconsistent_report;
        out["alarms"] = d.alarms;
        return out;
      });
}
