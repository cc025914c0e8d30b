// SPDX-License-Identifier: Apache-2.0
// Helpers for the Safety service tests: build a cycle's datagrams, run cycles.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>

#include "safestate/saf/safety_service.hpp"

namespace safestate::saf::test {

/// The model's CI constants (models/SafetyService.cfg) with the check interval 3.
inline constexpr Timing kSmall{2, 3, 2, 3};
inline constexpr std::uint32_t kOtherComponent = 0x0009'0909;

/// The peer a message of this kind comes from (a transport that binds senders, design §5).
inline Sender peer_of(const Message& m) { return m.id == MessageId::SetEstop ? Sender::Client : Sender::Subsystem; }

/// The messages of one cycle, each from the peer of its kind and fresh.
inline InboundBatch batch(std::initializer_list<Message> messages) {
  InboundBatch b{};
  for (const Message& m : messages) EXPECT_TRUE(b.push(encode(m), peer_of(m), true));
  return b;
}

/// Tags every datagram of a received batch as from the peer of its kind, fresh: the
/// in-process rigs have one sender per kind and no sender binding of their own.
inline void tag_by_kind(InboundBatch& b) {
  for (std::size_t i = 0; i < b.count; ++i) {
    Datagram& d = b.items[i];
    const DecodeResult r = decode(d.bytes.data(), d.size);
    d.from = r.ok() && r.message.id == MessageId::SetEstop ? Sender::Client : Sender::Subsystem;
    d.fresh = true;
  }
}

inline CycleResult run(SafetyService& s, std::initializer_list<Message> messages, bool hw = false) {
  return s.cycle(batch(messages), hw);
}

inline Message clear() { return Message::set_estop(false); }
inline Message pressed() { return Message::set_estop(true); }
inline Message health(Health h) { return Message::report_health(h); }
inline Message accepted() { return Message::confirm_control(ControlResponse::Accepted); }
inline Message refused() { return Message::confirm_control(ControlResponse::InsufficientAuthority); }
inline Message taken_by_other() { return Message::report_control(kOtherComponent, 255); }

/// A service in OPERATIONAL (A fired), with the given timers.
inline SafetyService operational(const Timing& t = kSmall) {
  SafetyService s{t, 225};
  (void)run(s, {});
  (void)run(s, {clear(), health(Health::Normal)});
  EXPECT_EQ(s.observe().state, SafState::Operational);
  return s;
}

/// Whether the outbox holds a message with this id.
inline const Message* find(const Outbox& out, MessageId id) {
  for (std::size_t i = 0; i < out.count; ++i) {
    if (out.messages[i].id == id) return &out.messages[i];
  }
  return nullptr;
}

}  // namespace safestate::saf::test
