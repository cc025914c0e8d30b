// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/subsystem_sim.hpp"

namespace safestate::saf {

std::size_t SubsystemSim::step() noexcept {
  std::size_t handled = 0;
  Datagram d{};
  std::uint16_t from = 0;
  while (ep_.receive_one(d, &from) == UdpError::None) {
    if (key_.present()) {
      Datagram opened{};
      const LinkOpened lo = link_open(d.bytes.data(), d.size, LinkDirection::ServiceToSubsystem, key_, rx_, opened);
      if (lo.verdict != LinkVerdict::Ok) {
        ++rejected_[static_cast<std::size_t>(lo.verdict)];
        continue;
      }
      d = opened;
    }
    const DecodeResult r = decode(d.bytes.data(), d.size);
    if (!r.ok()) continue;
    handle(r.message, from);
    ++handled;
  }
  return handled;
}

void SubsystemSim::send(std::uint16_t to, const Message& m) noexcept {
  const Encoded e = encode(m);
  if (key_.present()) {
    (void)ep_.send_to(to, link_seal(e, next_sequence_++, LinkDirection::SubsystemToService, key_));
  } else {
    (void)ep_.send_to(to, e);
  }
}

void SubsystemSim::report_control(std::uint16_t to) noexcept {
  send(to, Message::report_control(holder_, holder_authority_));
}

void SubsystemSim::handle(const Message& m, std::uint16_t from) noexcept {
  switch (m.id) {
    case MessageId::RequestControl:
      if (m.action == ControlAction::Release) {
        if (holder_ == m.component_id) {
          holder_ = 0;
          holder_authority_ = 0;
        }
        break;
      }
      // Access control: granted when free, to the holder again, or to an authority at
      // least the holder's; refused otherwise.
      if (holder_ == 0 || holder_ == m.component_id || m.authority >= holder_authority_) {
        holder_ = m.component_id;
        holder_authority_ = m.authority;
        holder_port_ = from;
        send(from, Message::confirm_control(ControlResponse::Accepted));
      } else {
        send(from, Message::confirm_control(ControlResponse::InsufficientAuthority));
      }
      break;
    case MessageId::QueryControl: report_control(from); break;
    case MessageId::SetSubsystemState:
      if (holder_ != 0 && from == holder_port_ && m.subsystem_state != state_) {
        state_ = m.subsystem_state;
        send(from, Message::report_subsystem_state(state_));
      }
      break;
    case MessageId::QueryHealthSummary: send(from, Message::report_health(health_)); break;
    default: break;
  }
}

void SubsystemSim::take_control(std::uint32_t component, std::uint8_t authority) noexcept {
  if (holder_ != 0 && authority < holder_authority_) return;
  const std::uint16_t previous = holder_port_;
  holder_ = component;
  holder_authority_ = authority;
  holder_port_ = 0;
  if (previous != 0) report_control(previous);
}

void SubsystemSim::release_other() noexcept {
  if (holder_port_ == 0) {
    holder_ = 0;
    holder_authority_ = 0;
  }
}

}  // namespace safestate::saf
