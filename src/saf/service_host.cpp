// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/service_host.hpp"

namespace safestate::saf {

ServiceHost::ServiceHost(const HostConfig& config) noexcept
    : config_(config),
      service_(config.parameters, config.component_id),
      intake_(config.intake),
      link_next_(config.link_sequence_start) {}

SequenceState ServiceHost::sequences() const noexcept {
  SequenceState s = intake_.sequences();
  s.service = link_next_;
  return s;
}

void ServiceHost::restore(const SequenceState& s) noexcept {
  intake_.restore(s);
  if (s.service > link_next_) link_next_ = s.service;
}

HostError ServiceHost::open() noexcept {
  if (client_.open(config_.address, config_.client_port) != UdpError::None) {
    errno_ = client_.last_errno();
    return HostError::ClientSocket;
  }
  if (subsystem_.open(config_.address, config_.subsystem_port) != UdpError::None) {
    errno_ = subsystem_.last_errno();
    client_ = UdpEndpoint{};
    return HostError::SubsystemSocket;
  }
  if (subsystem_.connect_to(config_.intake.subsystem) != UdpError::None) {
    errno_ = subsystem_.last_errno();
    client_ = UdpEndpoint{};
    subsystem_ = UdpEndpoint{};
    return HostError::Connect;
  }
  return HostError::None;
}

HostCycle ServiceHost::step(bool hardware_fault) noexcept {
  HostCycle c{};
  c.before = service_.observe().state;
  received_.clear();
  // The subsystem's answers first and bounded, so that a backlog on the client socket
  // cannot starve the control exchange that sets EMERGENCY.
  while (received_.count < kSubsystemReadsPerCycle) {
    Peer from{};
    if (subsystem_.receive_one(received_.items[received_.count], from) != UdpError::None) break;
    received_.sources[received_.count++] = Source{from, SocketRole::Subsystem};
  }
  const std::uint64_t dropped_before = client_.kernel_dropped();
  client_.receive_batch(received_, SocketRole::Client);
  c.received = received_.count;
  c.kernel_dropped = client_.kernel_dropped() - dropped_before;
  c.overflow = c.kernel_dropped > 0 || (received_.full() && client_.has_pending());
  if (c.overflow) ++overflow_cycles_;
  service_.count_inbound_dropped(c.kernel_dropped);
  c.intake = intake_.filter(received_, c.overflow, accepted_);
  const CycleResult r = service_.cycle(accepted_, hardware_fault);
  c.state_row = r.state_row;
  c.control_row = r.control_row;
  c.after = service_.observe().state;
  c.sent = r.outbox;
  for (std::size_t i = 0; i < r.outbox.count; ++i) {
    const Encoded e = encode(r.outbox.messages[i]);
    if (config_.intake.key.present()) {
      (void)subsystem_.send_to(config_.intake.subsystem,
                               link_seal(e, link_next_++, LinkDirection::ServiceToSubsystem, config_.intake.key));
    } else {
      (void)subsystem_.send_to(config_.intake.subsystem, e);
    }
  }
  return c;
}

}  // namespace safestate::saf
