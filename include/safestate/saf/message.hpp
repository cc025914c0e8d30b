// SPDX-License-Identifier: Apache-2.0
// One decoded message of any of the nine types (design §10).
#pragma once

#include <cstdint>

#include "safestate/saf/estop_form.hpp"
#include "safestate/saf/message_id.hpp"
#include "safestate/saf/wire_values.hpp"

namespace safestate::saf {

/// A message: its id and the fields its type carries (the others stay zero).
struct Message {
  MessageId id = MessageId::QueryControl;
  bool emergency = false;                                // Set Estop
  EstopForm estop_form = EstopForm::Seed;                // Set Estop: which wire form (design §14)
  std::uint64_t sequence = 0;                            // Set Estop (Sequenced, Authenticated)
  Health health = Health::Normal;                        // Report Health Summary
  ControlResponse response = ControlResponse::Accepted;  // Confirm Control
  // Report Control: holder (0 = nobody); Request Control: requester; Set Estop (Sequenced,
  // Authenticated): the Safety Client.
  std::uint32_t component_id = 0;
  std::uint8_t authority = 0;                                   // Report Control, Request Control
  SubsystemState subsystem_state = SubsystemState::Initialize;  // Report/Set Subsystem State
  ControlAction action = ControlAction::Request;                // Request Control

  [[nodiscard]] static constexpr Message set_estop(bool emergency_set) noexcept {
    Message m{};
    m.id = MessageId::SetEstop;
    m.emergency = emergency_set;
    return m;
  }
  [[nodiscard]] static constexpr Message report_health(Health h) noexcept {
    Message m{};
    m.id = MessageId::ReportHealthSummary;
    m.health = h;
    return m;
  }
  [[nodiscard]] static constexpr Message confirm_control(ControlResponse r) noexcept {
    Message m{};
    m.id = MessageId::ConfirmControl;
    m.response = r;
    return m;
  }
  [[nodiscard]] static constexpr Message report_control(std::uint32_t holder, std::uint8_t auth) noexcept {
    Message m{};
    m.id = MessageId::ReportControl;
    m.component_id = holder;
    m.authority = auth;
    return m;
  }
  [[nodiscard]] static constexpr Message report_subsystem_state(SubsystemState s) noexcept {
    Message m{};
    m.id = MessageId::ReportSubsystemState;
    m.subsystem_state = s;
    return m;
  }
  [[nodiscard]] static constexpr Message request_control(ControlAction a, std::uint8_t auth,
                                                         std::uint32_t requester) noexcept {
    Message m{};
    m.id = MessageId::RequestControl;
    m.action = a;
    m.authority = auth;
    m.component_id = requester;
    return m;
  }
  [[nodiscard]] static constexpr Message set_subsystem_state(SubsystemState s) noexcept {
    Message m{};
    m.id = MessageId::SetSubsystemState;
    m.subsystem_state = s;
    return m;
  }
  [[nodiscard]] static constexpr Message query(MessageId id) noexcept {
    Message m{};
    m.id = id;
    return m;
  }
};

}  // namespace safestate::saf
