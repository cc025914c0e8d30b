// SPDX-License-Identifier: Apache-2.0
// Sender binding, freshness and authentication of design §14, in the order the section
// lists them: codec, source, form, MAC, component id, sequence, overflow; with a key the
// subsystem link's trailer (§15) before all of them.
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

namespace {

IntakeReason link_reason(LinkVerdict v) noexcept {
  switch (v) {
    case LinkVerdict::Ok: return IntakeReason::None;
    case LinkVerdict::Unauthenticated: return IntakeReason::ReportUnauthenticated;
    case LinkVerdict::BadMac: return IntakeReason::ReportBadMac;
    case LinkVerdict::Replay: return IntakeReason::ReportReplay;
    case LinkVerdict::Stale: return IntakeReason::ReportStale;
  }
  return IntakeReason::ReportUnauthenticated;
}

}  // namespace

void Intake::restore(const SequenceState& s) noexcept {
  have_sequence_ = s.have_estop;
  highest_ = s.estop;
  link_.have = s.have_subsystem;
  link_.highest = s.subsystem;
}

SequenceState Intake::sequences() const noexcept {
  SequenceState s{};
  s.have_estop = have_sequence_;
  s.estop = highest_;
  s.have_subsystem = link_.have;
  s.subsystem = link_.highest;
  return s;
}

IntakeRejection Intake::judge(const Datagram& d, const Source& from, bool overflow, Datagram& opened) noexcept {
  IntakeRejection r{};
  r.source = from;
  opened = d;
  // With a key, everything on the subsystem socket is sealed (design §15): the trailer is
  // checked and removed first, so that the codec and the core see the seed's form.
  if (from.socket == SocketRole::Subsystem && config_.key.present()) {
    const LinkOpened lo =
        link_open(d.bytes.data(), d.size, LinkDirection::SubsystemToService, config_.key, link_, opened);
    if (lo.verdict != LinkVerdict::Ok) {
      r.reason = link_reason(lo.verdict);
      const DecodeResult seed = decode(d.bytes.data(), d.size);  // for the log: what it claimed to be
      if (seed.ok()) {
        r.decoded = true;
        r.id = seed.message.id;
      }
      ++counters_.rejected[static_cast<std::size_t>(r.reason)];
      return r;
    }
  }
  const DecodeResult dr = decode(opened.bytes.data(), opened.size);
  if (!dr.ok()) {
    r.reason = intake_reason_of(dr.error);
  } else {
    r.decoded = true;
    r.id = dr.message.id;
    if (!spec_of(r.id).incoming) {
      r.reason = IntakeReason::NotIncoming;
    } else if (r.id == MessageId::SetEstop) {
      r.reason = judge_estop(opened, dr.message, from, overflow);
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
    Datagram opened{};
    const IntakeRejection r = judge(in.items[i], in.sources[i], overflow, opened);
    if (r.reason == IntakeReason::None) {
      // Accepted: the core's tag is the socket the binding matched (a stale or replayed
      // Set Estop never gets here, so every accepted datagram is fresh).
      const Sender sender = in.sources[i].socket == SocketRole::Client ? Sender::Client : Sender::Subsystem;
      (void)out.push(opened.bytes.data(), opened.size, in.sources[i], sender, true);
    } else if (cycle.count < cycle.rejected.size()) {
      cycle.rejected[cycle.count++] = r;
    }
  }
  return cycle;
}

}  // namespace safestate::saf
