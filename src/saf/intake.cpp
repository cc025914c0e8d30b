// SPDX-License-Identifier: Apache-2.0
// Sender binding, freshness and authentication of design §14, in the order the section
// lists them: codec, source, form, MAC, component id, sequence, overflow.
#include "safestate/saf/intake.hpp"

namespace safestate::saf {
namespace {

bool from_subsystem_type(MessageId id) noexcept {
  return id == MessageId::ReportHealthSummary || id == MessageId::ConfirmControl || id == MessageId::ReportControl ||
         id == MessageId::ReportSubsystemState;
}

}  // namespace

IntakeReason Intake::judge_estop(const Datagram& d, const Message& m, const Source& from, bool overflow) noexcept {
  if (from.socket != SocketRole::Client || from.peer != config_.client) return IntakeReason::EstopWrongSource;
  switch (m.estop_form) {
    case EstopForm::Seed:
      if (config_.require_sequence || config_.key.present()) return IntakeReason::EstopUnsequenced;
      // The seed's form carries neither id nor sequence: only the source and overflow apply.
      return overflow && !m.emergency ? IntakeReason::EstopClearInOverflow : IntakeReason::None;
    case EstopForm::Sequenced:
      if (config_.key.present()) return IntakeReason::EstopUnauthenticated;
      break;
    case EstopForm::Authenticated:
      if (!estop_mac_valid(d.bytes.data(), d.size, config_.key)) return IntakeReason::EstopBadMac;
      break;
  }
  if (m.component_id != config_.client_component_id) return IntakeReason::EstopWrongComponent;
  if (have_sequence_ && m.sequence <= highest_) {
    return highest_ - m.sequence < config_.replay_window ? IntakeReason::EstopReplay : IntakeReason::EstopStale;
  }
  // Fresh and authentic: the sequence advances even when the overflow rule below rejects a
  // clear, so that the same datagram cannot be replayed once the flood is over.
  have_sequence_ = true;
  highest_ = m.sequence;
  return overflow && !m.emergency ? IntakeReason::EstopClearInOverflow : IntakeReason::None;
}

IntakeRejection Intake::judge(const Datagram& d, const Source& from, bool overflow) noexcept {
  IntakeRejection r{};
  r.source = from;
  const DecodeResult dr = decode(d.bytes.data(), d.size);
  if (!dr.ok()) {
    r.reason = intake_reason_of(dr.error);
  } else {
    r.decoded = true;
    r.id = dr.message.id;
    if (!spec_of(r.id).incoming) {
      r.reason = IntakeReason::NotIncoming;
    } else if (r.id == MessageId::SetEstop) {
      r.reason = judge_estop(d, dr.message, from, overflow);
    } else if (from_subsystem_type(r.id) && (from.socket != SocketRole::Subsystem || from.peer != config_.subsystem)) {
      r.reason = IntakeReason::ReportWrongSource;
    }
  }
  if (r.reason == IntakeReason::None) {
    ++counters_.accepted;
  } else {
    ++counters_.rejected[static_cast<std::size_t>(r.reason)];
  }
  return r;
}

IntakeCycle Intake::filter(const InboundBatch& in, bool overflow, InboundBatch& out) noexcept {
  IntakeCycle cycle{};
  out.clear();
  for (std::size_t i = 0; i < in.count && i < in.items.size(); ++i) {
    const IntakeRejection r = judge(in.items[i], in.sources[i], overflow);
    if (r.reason == IntakeReason::None) {
      // Accepted: the core's tag is the socket the binding matched (a stale or replayed
      // Set Estop never gets here, so every accepted datagram is fresh).
      const Sender sender = in.sources[i].socket == SocketRole::Client ? Sender::Client : Sender::Subsystem;
      (void)out.push(in.items[i].bytes.data(), in.items[i].size, in.sources[i], sender, true);
    } else if (cycle.count < cycle.rejected.size()) {
      cycle.rejected[cycle.count++] = r;
    }
  }
  return cycle;
}

}  // namespace safestate::saf
