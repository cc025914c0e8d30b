// SPDX-License-Identifier: Apache-2.0
// safestate._saf_net: the deployed Safety service (ServiceHost: sockets, intake, core) for
// `safestate saf serve`, and the key file and Set Estop extension for the simulators
// (docs/design/safety-service.md §14). The process around it is Python
// (python/safestate/saf_service/).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "safestate/saf/estop_extension.hpp"
#include "safestate/saf/key_file.hpp"
#include "safestate/saf/link_auth.hpp"
#include "safestate/saf/sequence_file.hpp"
#include "safestate/saf/service_host.hpp"
#include "safestate/saf/sha256.hpp"

namespace py = pybind11;
using namespace safestate::saf;  // NOLINT

namespace {

py::str str(std::string_view s) { return py::str(s.data(), s.size()); }

py::bytes to_bytes(const std::uint8_t* data, std::size_t size) {
  return py::bytes(reinterpret_cast<const char*>(data), size);
}

std::uint32_t address_of(const std::string& text, const char* what) {
  const std::optional<std::uint32_t> a = parse_ipv4(text);
  if (!a) throw py::value_error(std::string(what) + ": '" + text + "' is not an IPv4 address (a.b.c.d)");
  return *a;
}

MacKey key_of(const std::optional<py::bytes>& key) {
  MacKey k{};
  if (!key) return k;
  const std::string_view v = *key;
  if (v.size() < kMinKeyBytes || v.size() > k.bytes.size()) {
    throw py::value_error("the key must have 16 to 64 bytes");
  }
  std::memcpy(k.bytes.data(), v.data(), v.size());
  k.size = v.size();
  return k;
}

Config parameters_of(const py::dict& p) {
  Config c{};
  c.cycle_interval_s = p["CYCLEINTERVAL"].cast<double>();
  c.estop_timeout_s = p["ESTOPTIMEOUT"].cast<double>();
  c.report_data_timeout_s = p["REPORTDATATIMEOUT"].cast<double>();
  c.message_interval_s = p["MESSAGEINTERVAL"].cast<double>();
  c.check_interval_s = p["CHECKINTERVAL"].cast<double>();
  c.authority_code = p["AUTHORITYCODE"].cast<std::uint8_t>();
  return c;
}

py::str message_name(MessageId id) { return str(spec_of(id).name); }

py::str role_name(SocketRole r) {
  switch (r) {
    case SocketRole::Client: return str("client");
    case SocketRole::Subsystem: return str("subsystem");
    case SocketRole::Unknown: break;
  }
  return str("unknown");
}

py::dict cycle_dict(const HostCycle& c) {
  py::dict d;
  d["before"] = str(to_string(c.before));
  d["after"] = str(to_string(c.after));
  d["state_row"] = str(c.state_row);
  d["control_row"] = str(c.control_row);
  d["received"] = c.received;
  d["overflow"] = c.overflow;
  d["kernel_dropped"] = c.kernel_dropped;
  py::list rejected;
  for (std::size_t i = 0; i < c.intake.count; ++i) {
    const IntakeRejection& r = c.intake.rejected[i];
    py::dict x;
    x["reason"] = str(to_string(r.reason));
    x["source"] = str(to_text(r.source.peer).view());
    x["socket"] = role_name(r.source.socket);
    x["message"] = r.decoded ? message_name(r.id) : str("");
    rejected.append(x);
  }
  d["rejected"] = rejected;
  py::list sent;
  for (std::size_t i = 0; i < c.sent.count; ++i) {
    const Message& m = c.sent.messages[i];
    std::string name(spec_of(m.id).name);
    if (m.id == MessageId::SetSubsystemState) {
      name += m.subsystem_state == SubsystemState::Emergency ? "(EMERGENCY)" : "(OPERATIONAL)";
    } else if (m.id == MessageId::RequestControl) {
      name += m.action == ControlAction::Release ? "(RELEASE)" : "(REQUEST)";
    }
    sent.append(name);
  }
  d["sent"] = sent;
  return d;
}

py::dict counters(const ServiceHost& h) {
  py::dict d;
  const IntakeCounters& c = h.intake().counters();
  d["accepted"] = c.accepted;
  py::dict rejected;
  for (std::size_t i = 1; i < kIntakeReasonCount; ++i) {
    rejected[str(to_string(static_cast<IntakeReason>(i)))] = c.rejected[i];
  }
  d["rejected"] = rejected;
  d["kernel_dropped"] = h.kernel_dropped();
  d["overflow_cycles"] = h.overflow_cycles();
  d["send_dropped"] = h.send_dropped();
  d["cycles"] = h.service().diagnostics().cycles;
  return d;
}

py::object optional_u64(bool have, std::uint64_t v) { return have ? py::object(py::int_(v)) : py::object(py::none()); }

py::dict sequence_dict(const SequenceState& s) {
  py::dict d;
  d["estop"] = optional_u64(s.have_estop, s.estop);
  d["subsystem"] = optional_u64(s.have_subsystem, s.subsystem);
  d["service"] = s.service;
  return d;
}

SequenceState sequence_state(const py::object& estop, const py::object& subsystem, std::uint64_t service) {
  SequenceState s{};
  s.have_estop = !estop.is_none();
  s.estop = s.have_estop ? estop.cast<std::uint64_t>() : 0;
  s.have_subsystem = !subsystem.is_none();
  s.subsystem = s.have_subsystem ? subsystem.cast<std::uint64_t>() : 0;
  s.service = service;
  return s;
}

std::string sequence_file_error(const std::string& path, const SequenceFileResult& r) {
  std::string why = path + ": sequence file " + std::string(to_string(r.error));
  if (r.error == SequenceFileError::CannotOpen || r.error == SequenceFileError::CannotWrite) {
    why += std::string(" (") + std::strerror(r.error_number) + ")";
  } else if (r.error == SequenceFileError::Permissions) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", r.mode);
    why += std::string(", it is ") + mode;
  } else if (r.error == SequenceFileError::BadFormat) {
    why = path + ":" + std::to_string(r.line) + ": sequence file: expected '" + std::string(r.expected) + "'";
  }
  return why;
}

}  // namespace

PYBIND11_MODULE(_saf_net, m) {
  m.doc() = "The deployed Safety service: UDP sockets, sender binding and freshness, the core.";
  m.attr("REASONS") = [] {
    py::list l;
    for (std::size_t i = 1; i < kIntakeReasonCount; ++i) l.append(str(to_string(static_cast<IntakeReason>(i))));
    return l;
  }();

  m.def(
      "validate_parameters", [](const py::dict& p) { return str(to_string(parameters_of(p).validate())); },
      py::arg("parameters"), "NONE when the six SAF-04 parameters (seconds) are usable, else the ConfigError name.");

  m.def(
      "load_key_file",
      [](const std::string& path) {
        const KeyFileResult r = load_key_file(path.c_str());
        if (r.error == KeyFileError::None) return to_bytes(r.key.bytes.data(), r.key.size);
        std::string why(to_string(r.error));
        if (r.error == KeyFileError::CannotOpen) why += std::string(" (") + std::strerror(r.error_number) + ")";
        if (r.error == KeyFileError::Permissions) {
          char mode[8];
          std::snprintf(mode, sizeof mode, "%04o", r.mode);
          why += std::string(", it is ") + mode;
        }
        throw py::value_error(path + ": key file " + why);
      },
      py::arg("path"), "The HMAC key (bytes) from a key file; ValueError naming the file and the reason.");

  m.def(
      "hmac_sha256",
      [](const py::bytes& key, const py::bytes& data) {
        const std::string_view k = key;
        const std::string_view v = data;
        const Digest d = hmac_sha256(reinterpret_cast<const std::uint8_t*>(k.data()), k.size(),
                                     reinterpret_cast<const std::uint8_t*>(v.data()), v.size());
        return to_bytes(d.data(), d.size());
      },
      py::arg("key"), py::arg("data"), "HMAC-SHA256 (the C++ implementation).");

  m.def(
      "encode_set_estop",
      [](bool emergency, std::uint32_t client_id, std::uint64_t sequence, const std::optional<py::bytes>& key) {
        const Encoded e = encode_set_estop(emergency, client_id, sequence, key_of(key));
        return to_bytes(e.bytes.data(), e.size);
      },
      py::arg("emergency"), py::arg("client_id"), py::arg("sequence"), py::arg("key") = py::none(),
      "A Set Estop of the extension (design §14): Sequenced, or Authenticated with a key.");

  m.def(
      "load_sequence_file",
      [](const std::string& path) -> py::object {
        const SequenceFileResult r = load_sequence_file(path.c_str());
        if (r.error == SequenceFileError::Missing) return py::none();
        if (r.error != SequenceFileError::None) throw py::value_error(sequence_file_error(path, r));
        return sequence_dict(r.state);
      },
      py::arg("path"),
      "The replay state {estop, subsystem, service} of a sequence file, None when it does not exist; "
      "ValueError naming the file (and line) and what was expected.");

  m.def(
      "store_sequence_file",
      [](const std::string& path, const py::object& estop, const py::object& subsystem, std::uint64_t service) {
        const SequenceState state = sequence_state(estop, subsystem, service);
        SequenceFileResult r{};
        {
          // The fsyncs take milliseconds: the service's writer thread stores while the
          // scan cycles go on.
          py::gil_scoped_release release;
          r = store_sequence_file(path.c_str(), state);
        }
        if (r.error != SequenceFileError::None) throw py::value_error(sequence_file_error(path, r));
      },
      py::arg("path"), py::arg("estop"), py::arg("subsystem"), py::arg("service"),
      "Writes the replay state atomically (temporary file 0600, fsync, rename); ValueError with the reason.");

  m.def(
      "link_seal",
      [](const py::bytes& message, std::uint64_t sequence, bool to_subsystem, const py::bytes& key) {
        const std::string_view v = message;
        Encoded e{};
        if (v.size() > e.bytes.size()) throw py::value_error("a message is at most 64 bytes");
        std::memcpy(e.bytes.data(), v.data(), v.size());
        e.size = v.size();
        const Encoded s =
            link_seal(e, sequence, to_subsystem ? LinkDirection::ServiceToSubsystem : LinkDirection::SubsystemToService,
                      key_of(std::optional<py::bytes>(key)));
        return to_bytes(s.bytes.data(), s.size);
      },
      py::arg("message"), py::arg("sequence"), py::arg("to_subsystem"), py::arg("key"),
      "The link's sealed form of a seed-form message (design §15; the C++ implementation).");

  py::class_<ServiceHost, std::unique_ptr<ServiceHost>>(m, "ServiceHost", py::module_local())
      .def(py::init([](const std::string& address, std::uint16_t client_port, std::uint16_t subsystem_port,
                       std::uint32_t component_id, const std::string& client_address, std::uint16_t client_peer_port,
                       std::uint32_t client_component_id, const std::string& subsystem_address,
                       std::uint16_t subsystem_peer_port, const py::dict& parameters, bool require_sequence,
                       std::uint64_t replay_window, const std::optional<py::bytes>& key,
                       std::uint64_t link_sequence_start) {
             HostConfig c{};
             c.parameters = parameters_of(parameters);
             c.component_id = component_id;
             c.address = address_of(address, "service.address");
             c.client_port = client_port;
             c.subsystem_port = subsystem_port;
             c.intake.client = Peer{address_of(client_address, "client.address"), client_peer_port};
             c.intake.client_component_id = client_component_id;
             c.intake.subsystem = Peer{address_of(subsystem_address, "subsystem.address"), subsystem_peer_port};
             c.intake.require_sequence = require_sequence;
             c.intake.replay_window = replay_window;
             c.intake.key = key_of(key);
             c.link_sequence_start = link_sequence_start;
             return std::make_unique<ServiceHost>(c);
           }),
           py::kw_only(), py::arg("address"), py::arg("client_port"), py::arg("subsystem_port"),
           py::arg("component_id"), py::arg("client_address"), py::arg("client_peer_port"),
           py::arg("client_component_id"), py::arg("subsystem_address"), py::arg("subsystem_peer_port"),
           py::arg("parameters"), py::arg("require_sequence") = true, py::arg("replay_window") = 64,
           py::arg("key") = py::none(), py::arg("link_sequence_start") = 1)
      .def(
          "open",
          [](ServiceHost& h) {
            const HostError e = h.open();
            if (e != HostError::None) {
              throw py::value_error(std::string(to_string(e)) + ": " + std::strerror(h.last_errno()));
            }
          },
          "Binds both sockets and connects the subsystem one; ValueError with the reason.")
      .def(
          "step", [](ServiceHost& h, bool hardware_fault) { return cycle_dict(h.step(hardware_fault)); },
          py::arg("hardware_fault") = false, "One scan cycle; what it did (state change, rejections, sent).")
      .def("counters", &counters, "Accepted, rejected per reason, kernel drops, overflow cycles.")
      .def(
          "sequences", [](const ServiceHost& h) { return sequence_dict(h.sequences()); },
          "The replay state for the sequence file: {estop, subsystem, service}.")
      .def(
          "restore",
          [](ServiceHost& h, const py::object& estop, const py::object& subsystem, std::uint64_t service) {
            h.restore(sequence_state(estop, subsystem, service));
          },
          py::arg("estop"), py::arg("subsystem"), py::arg("service"),
          "Restores a sequence file's state before the first cycle (our own next sequence only rises).")
      .def_property_readonly("state", [](const ServiceHost& h) { return str(to_string(h.service().observe().state)); })
      .def_property_readonly("client_port", &ServiceHost::client_port)
      .def_property_readonly("subsystem_port", &ServiceHost::subsystem_port)
      .def_property_readonly("config_error",
                             [](const ServiceHost& h) { return str(to_string(h.service().config_error())); });
}
