// SPDX-License-Identifier: Apache-2.0
// The Safety service: intake (design §5), the rows of §6 and §7 from transition_table.hpp,
// the periodic queries of §8.
#include "safestate/saf/safety_service.hpp"

namespace safestate::saf {
namespace {

constexpr Timing kFaultTiming{};  // the defaults, used when the Config is invalid

std::uint32_t saturating_inc(std::uint32_t v, std::uint32_t max) noexcept { return v < max ? v + 1 : v; }

HealthView view_of(Health h) noexcept {
  switch (h) {
    case Health::Normal: return HealthView::Normal;
    case Health::Warning: return HealthView::Warning;
    case Health::Error: return HealthView::Error;
    case Health::Fatal: return HealthView::Fatal;
  }
  return HealthView::Fatal;
}

bool raises_emergency(SafState s) noexcept { return s != SafState::Operational; }

}  // namespace

SafetyService::SafetyService(const Config& config, std::uint32_t component_id) noexcept
    : timing_(config.validate() == ConfigError::None ? config.timing() : kFaultTiming),
      authority_(config.authority_code),
      component_id_(component_id),
      config_error_(config.validate()) {
  if (config_error_ != ConfigError::None) obs_.state = SafState::Fault;
}

namespace {
ConfigError check(const Timing& t) noexcept {
  for (std::uint32_t c : {t.estop_timeout, t.report_data_timeout, t.message_interval, t.check_interval}) {
    if (c == 0) return ConfigError::TimeInvalid;
    if (c > kMaxTimerCycles) return ConfigError::TooManyCycles;
  }
  return ConfigError::None;
}
}  // namespace

SafetyService::SafetyService(const Timing& timing, std::uint8_t authority_code, std::uint32_t component_id) noexcept
    : timing_(check(timing) == ConfigError::None ? timing : kFaultTiming),
      authority_(authority_code),
      component_id_(component_id),
      config_error_(check(timing)) {
  if (config_error_ != ConfigError::None) obs_.state = SafState::Fault;
}

bool SafetyService::estop_timed_out() const noexcept {
  return obs_.estop != EstopView::None && obs_.estop_age > timing_.estop_timeout;
}

bool SafetyService::health_bad() const noexcept {
  return obs_.health == HealthView::Error || obs_.health == HealthView::Fatal ||
         obs_.health_age > timing_.report_data_timeout;
}

bool SafetyService::danger() const noexcept {
  return obs_.estop == EstopView::Set || estop_timed_out() || health_bad();
}

ControlEvent SafetyService::intake(const InboundBatch& inbound) noexcept {
  bool estop_seen = false;
  bool health_seen = false;
  ControlEvent ev = ControlEvent::None;
  for (std::size_t i = 0; i < inbound.count && i < inbound.items.size(); ++i) {
    const Datagram& d = inbound.items[i];
    const DecodeResult r = decode(d.bytes.data(), d.size);
    DecodeError error = r.error;
    if (r.ok() && !spec_of(r.message.id).incoming) error = DecodeError::NotIncoming;
    if (error != DecodeError::None) {
      ++diag_.rejected[static_cast<std::size_t>(error)];
      continue;
    }
    ++diag_.accepted;
    const Message& m = r.message;
    switch (m.id) {
      case MessageId::SetEstop:
        obs_.estop = m.emergency ? EstopView::Set : EstopView::Clear;
        estop_seen = true;
        break;
      case MessageId::ReportHealthSummary:
        obs_.health = view_of(m.health);
        health_seen = true;
        break;
      case MessageId::ConfirmControl:
        ev = m.response == ControlResponse::Accepted ? ControlEvent::Accepted : ControlEvent::Refused;
        break;
      case MessageId::ReportControl:
        ev = m.component_id == component_id_ ? ControlEvent::Accepted : ControlEvent::Other;
        break;
      case MessageId::ReportSubsystemState:
        diag_.subsystem_state_known = true;
        diag_.subsystem_state = m.subsystem_state;
        resend_emergency_ = m.subsystem_state != SubsystemState::Emergency;
        break;
      default: break;  // outgoing types were rejected above
    }
  }
  obs_.estop_age = estop_seen ? 0 : saturating_inc(obs_.estop_age, timing_.estop_timeout + 1);
  obs_.health_age = health_seen ? 0 : saturating_inc(obs_.health_age, timing_.report_data_timeout + 1);
  return ev;
}

bool SafetyService::state_guard(StateGuard g, bool hardware_fault) const noexcept {
  switch (g) {
    case StateGuard::True: return true;
    case StateGuard::HardwareFault: return hardware_fault;
    case StateGuard::PairedAndSafe: return obs_.estop != EstopView::None && !danger();
    case StateGuard::Danger: return danger();
    case StateGuard::EstopTimedOut: return estop_timed_out();
    case StateGuard::ClearAndSafe: return obs_.estop == EstopView::Clear && !danger();
  }
  return false;
}

bool SafetyService::control_guard(ControlGuard g, ControlEvent ev) const noexcept {
  switch (g) {
    case ControlGuard::True: return true;
    case ControlGuard::EventAccepted: return ev == ControlEvent::Accepted;
    case ControlGuard::EventRefused: return ev == ControlEvent::Refused;
    case ControlGuard::EventOther: return ev == ControlEvent::Other;
    case ControlGuard::AgeReportDataTimeout: return obs_.control_age >= timing_.report_data_timeout;
    case ControlGuard::AgeMessageInterval: return obs_.control_age >= timing_.message_interval;
    case ControlGuard::EventAcceptedNoRelease:
      return ev == ControlEvent::Accepted && obs_.out_request == OutRequest::None;
  }
  return false;
}

void SafetyService::apply(StateEffect e) noexcept {
  switch (e) {
    case StateEffect::Stay: break;
    case StateEffect::EnterFault: obs_.state = SafState::Fault; break;
    case StateEffect::EnterEmergency: obs_.state = SafState::Emergency; break;
    case StateEffect::LeaveEmergency:
      obs_.state = SafState::Operational;
      obs_.out_set_state = obs_.control == ControlStatus::Held ? OutSetState::Operational : OutSetState::None;
      obs_.out_request = OutRequest::Release;
      obs_.control = ControlStatus::Released;
      obs_.control_age = 0;
      break;
  }
}

void SafetyService::apply(ControlEffect e) noexcept {
  switch (e) {
    case ControlEffect::Request:
      obs_.out_request = OutRequest::Request;
      obs_.control = ControlStatus::Requested;
      obs_.control_age = 0;
      break;
    case ControlEffect::Grant:
      obs_.control = ControlStatus::Held;
      obs_.control_age = 0;
      obs_.out_set_state = OutSetState::Emergency;
      break;
    case ControlEffect::Refuse:
      obs_.control = ControlStatus::Refused;
      obs_.control_age = 0;
      break;
    case ControlEffect::Refresh: obs_.control_age = 0; break;
    case ControlEffect::ReleaseAgain: obs_.out_request = OutRequest::Release; break;
    case ControlEffect::Tick: {
      const std::uint32_t max = timing_.report_data_timeout > timing_.message_interval ? timing_.report_data_timeout
                                                                                       : timing_.message_interval;
      obs_.control_age = saturating_inc(obs_.control_age, max);
      break;
    }
  }
}

void SafetyService::add(Outbox& out, const Message& m) const noexcept {
  if (out.count < out.messages.size()) out.messages[out.count++] = m;
}

CycleResult SafetyService::cycle(const InboundBatch& inbound, bool hardware_fault) noexcept {
  CycleResult result{};
  obs_.out_request = OutRequest::None;
  obs_.out_set_state = OutSetState::None;
  resend_emergency_ = false;
  const ControlEvent ev = intake(inbound);

  for (const StateRow& row : kStateRows) {
    if ((row.source & bit(obs_.state)) == 0 || !state_guard(row.guard, hardware_fault)) continue;
    result.state_row = row.id;
    apply(row.effect);
    break;
  }
  for (const ControlRow& row : kControlRows) {
    if ((row.states & bit(obs_.state)) == 0 || (row.control & bit(obs_.control)) == 0 ||
        !control_guard(row.guard, ev)) {
      continue;
    }
    result.control_row = row.id;
    apply(row.effect);
    break;
  }
  if (raises_emergency(obs_.state)) {
    // C++ only (design §7): someone changed the subsystem state behind our back.
    const std::uint64_t since = diag_.cycles - diag_.last_set_emergency_cycle;
    if (resend_emergency_ && obs_.control == ControlStatus::Held && obs_.out_set_state == OutSetState::None &&
        since >= timing_.message_interval) {
      obs_.out_set_state = OutSetState::Emergency;
    }
  }

  Outbox& out = result.outbox;
  // Set Subsystem State first: setting OPERATIONAL needs the control the release gives up.
  if (obs_.out_set_state != OutSetState::None) {
    const bool emergency = obs_.out_set_state == OutSetState::Emergency;
    if (emergency) diag_.last_set_emergency_cycle = diag_.cycles;
    add(out, Message::set_subsystem_state(emergency ? SubsystemState::Emergency : SubsystemState::Operational));
  }
  if (obs_.out_request != OutRequest::None) {
    add(out, Message::request_control(
                 obs_.out_request == OutRequest::Release ? ControlAction::Release : ControlAction::Request, authority_,
                 component_id_));
  }
  if (diag_.cycles % timing_.message_interval == 0) add(out, Message::query(MessageId::QueryHealthSummary));
  if (diag_.cycles % timing_.check_interval == 0) {
    add(out, Message::query(MessageId::QueryControl));
  }
  ++diag_.cycles;
  return result;
}

}  // namespace safestate::saf
