// SPDX-License-Identifier: Apache-2.0
// libFuzzer target for the Safety service codec and intake (SAF-03, design §14): any byte
// string is decoded; a rejected datagram must not change the service; an accepted one must
// encode back to the same bytes (an authenticated Set Estop up to its MAC); the deployed
// intake judges it from the client's and from another source without crashing, and
// accepts nothing from another source, and on the subsystem socket (with a key) nothing but
// a datagram that is exactly a sealed one. Built with clang -fsanitize=fuzzer,address,undefined
// by bench/saf_fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "safestate/saf/intake.hpp"
#include "safestate/saf/safety_service.hpp"

using namespace safestate::saf;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const DecodeResult r = decode(data, size);
  if (r.ok()) {
    const Encoded e = encode(r.message);
    // The codec does not compute the MAC (estop_extension.cpp does): compare up to it.
    const bool mac = r.message.id == MessageId::SetEstop && r.message.estop_form == EstopForm::Authenticated;
    const std::size_t compared = mac ? kEstopMacCovered : size;
    if (e.size != size || std::memcmp(e.bytes.data(), data, compared) != 0) std::abort();  // round trip
  }
  {
    IntakeConfig c{};
    c.client = Peer{kLoopback, 4000};
    c.client_component_id = 0x0001'0300;
    c.subsystem = Peer{kLoopback, 4001};
    c.key.size = 32;
    Intake intake{c};
    Datagram d{};
    d.size = size;
    if (size > 0) std::memcpy(d.bytes.data(), data, size < d.bytes.size() ? size : d.bytes.size());
    (void)intake.judge(d, Source{c.client, SocketRole::Client}, size > 0 && data[0] == 0x01);
    // With the key, the subsystem socket accepts only a sealed datagram whose MAC verifies
    // (design §15): sealing what it handed on, with its sequence, gives the input back.
    Datagram opened{};
    const IntakeRejection sub = intake.judge(d, Source{c.subsystem, SocketRole::Subsystem}, false, opened);
    if (sub.reason == IntakeReason::None) {
      Encoded inner{};
      inner.size = opened.size;
      std::memcpy(inner.bytes.data(), opened.bytes.data(), opened.size);
      const std::uint64_t seq = intake.sequences().subsystem;
      const Encoded again = link_seal(inner, seq, LinkDirection::SubsystemToService, c.key);
      if (again.size != size || std::memcmp(again.bytes.data(), data, size) != 0) std::abort();
    }
    const IntakeRejection other = intake.judge(d, Source{Peer{kLoopback, 4002}, SocketRole::Client}, false);
    if (other.reason == IntakeReason::None) std::abort();  // nothing is accepted from an unconfigured source
  }
  // Through the service: the datagram alone, then split into up to 16 datagrams.
  static constexpr Timing kTiming{2, 3, 2, 3};
  SafetyService a{kTiming, 225};
  SafetyService b{kTiming, 225};
  InboundBatch batch{};
  (void)batch.push(data, size);
  (void)a.cycle(batch, false);
  (void)b.cycle(InboundBatch{}, false);
  if (!r.ok() || !spec_of(r.message.id).incoming) {
    if (!(a.observe() == b.observe())) std::abort();          // a rejected datagram changed the state
    if (a.diagnostics().rejected_total() != 1) std::abort();  // and was counted once
  }
  batch.clear();
  for (std::size_t off = 0; off < size && batch.count < kMaxInboundPerCycle;) {
    const std::size_t n = 1 + data[off] % 24;
    const std::size_t len = off + n <= size ? n : size - off;
    (void)batch.push(data + off, len);
    off += len;
  }
  (void)a.cycle(batch, size > 0 && data[0] == 0xFF);
  return 0;
}
