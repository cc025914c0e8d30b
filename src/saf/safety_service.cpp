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

/// The peer a message of this kind must come from (design §5).
Sender peer_of(MessageId id) noexcept { return id == MessageId::SetEstop ? Sender::Client : Sender::Subsystem; }

}  // namespace

SafetyService::SafetyService(const Config& config, std::uint32_t component_id) noexcept
    : timing_(config.validate() == ConfigError::None ? config.timing() : kFaultTiming),
      authority_(config.authority_code),
      component_id_(component_id),
      config_error_(config.validate()) {
  if (config_error_ != ConfigError::None) obs_.state = SafState::Fault;
  obs_.set_age = timing_.message_interval;
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
  obs_.set_age = timing_.message_interval;
}

bool SafetyService::estop_timed_out() const noexcept {
  return obs_.estop != EstopView::None && obs_.estop_age >= timing_.estop_timeout;
}

bool SafetyService::health_bad() const noexcept {
  return obs_.health == HealthView::Error || obs_.health == HealthView::Fatal ||
         obs_.health_age > timing_.report_data_timeout;
}

bool SafetyService::health_known_good() const noexcept {
  return (obs_.health == HealthView::Normal || obs_.health == HealthView::Warning) &&
         obs_.health_age <= timing_.report_data_timeout;
}

bool SafetyService::danger() const noexcept {
  return obs_.estop == EstopView::Set || estop_timed_out() || health_bad();
}

SafetyService::Intake SafetyService::intake(const InboundBatch& inbound) noexcept {
  bool estop_seen = false;
  bool health_seen = false;
  Intake in{};
  for (std::size_t i = 0; i < inbound.count && i < inbound.items.size(); ++i) {
    const Datagram& d = inbound.items[i];
    const DecodeResult r = decode(d.bytes.data(), d.size);
    DecodeError error = r.error;
    if (r.ok() && !spec_of(r.message.id).incoming) error = DecodeError::NotIncoming;
    if (error != DecodeError::None) {
      ++diag_.rejected[static_cast<std::size_t>(error)];
      continue;
    }
    const Message& m = r.message;
    // Sender binding and freshness (design §5): only the peer of the message's kind, and
    // only inside the replay window; anything else changes nothing but a counter.
    if (d.from != peer_of(m.id)) {
      ++diag_.rejected_source;
      continue;
    }
    if (!d.fresh) {
      ++diag_.rejected_stale;
      continue;
    }
    ++diag_.accepted;
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
        in.event = m.response == ControlResponse::Accepted ? ControlEvent::Accepted : ControlEvent::Refused;
        break;
      case MessageId::ReportControl:
        if (m.component_id != component_id_) {
          in.event = ControlEvent::Other;
        } else if (m.authority == authority_) {
          in.event = ControlEvent::Us;
        } else {
          ++diag_.inconsistent_report;  // names us with an authority we never asked with
        }
        break;
      case MessageId::ReportSubsystemState:
        diag_.subsystem_state_known = true;
        diag_.subsystem_state = m.subsystem_state;
        in.subsystem_not_emergency = m.subsystem_state != SubsystemState::Emergency;
        break;
      default: break;  // outgoing types were rejected above
    }
  }
  obs_.estop_age = estop_seen ? 0 : saturating_inc(obs_.estop_age, timing_.estop_timeout);
  obs_.health_age = health_seen ? 0 : saturating_inc(obs_.health_age, timing_.report_data_timeout + 1);
  obs_.set_age = saturating_inc(obs_.set_age, timing_.message_interval);
  return in;
}

bool SafetyService::state_guard(StateGuard g, bool hardware_fault) const noexcept {
  switch (g) {
    case StateGuard::True: return true;
    case StateGuard::HardwareFault: return hardware_fault;
    case StateGuard::PairedAndSafe: return obs_.estop != EstopView::None && !danger() && health_known_good();
    case StateGuard::Danger: return danger();
    case StateGuard::EstopTimedOut: return estop_timed_out();
    case StateGuard::ClearSafeAndTold:
      // D waits until the subsystem was told EMERGENCY (control held) or the contest is lost.
      return obs_.estop == EstopView::Clear && !danger() && health_known_good() &&
             (obs_.control == ControlStatus::Held || obs_.control == ControlStatus::Refused);
  }
  return false;
}

bool SafetyService::control_guard(ControlGuard g, ControlEvent ev) const noexcept {
  switch (g) {
    case ControlGuard::True: return true;
    case ControlGuard::Granted:
      return ev == ControlEvent::Us || (ev == ControlEvent::Accepted && obs_.control == ControlStatus::Requested);
    case ControlGuard::EventRefused: return ev == ControlEvent::Refused;
    case ControlGuard::EventUs: return ev == ControlEvent::Us;
    case ControlGuard::EventOther: return ev == ControlEvent::Other;
    case ControlGuard::AgeReportDataTimeout: return obs_.control_age >= timing_.report_data_timeout;
    case ControlGuard::AgeMessageInterval: return obs_.control_age >= timing_.message_interval;
    case ControlGuard::EventUsNoRelease: return ev == ControlEvent::Us && obs_.out_request == OutRequest::None;
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
      obs_.alarm = false;
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
    case ControlEffect::RequestAlarm:
      apply(ControlEffect::Request);
      obs_.alarm = true;
      ++diag_.alarms;
      break;
    case ControlEffect::Grant:
      obs_.control = ControlStatus::Held;
      obs_.control_age = 0;
      obs_.out_set_state = OutSetState::Emergency;
      obs_.set_age = 0;
      obs_.alarm = false;
      break;
    case ControlEffect::Refuse:
      obs_.control = ControlStatus::Refused;
      obs_.control_age = 0;
      obs_.alarm = true;
      ++diag_.alarms;
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

void SafetyService::resend_step(bool subsystem_not_emergency) noexcept {
  // Design §7: a Report Subsystem State other than EMERGENCY while we hold control makes a
  // re-send due; it waits for MESSAGEINTERVAL since the last Set Subsystem State(EMERGENCY)
  // (deferred, never dropped). Without control nothing is due and the interval is over.
  if (!raises_emergency(obs_.state) || obs_.control != ControlStatus::Held) {
    obs_.resend = false;
    obs_.set_age = timing_.message_interval;
    if (!raises_emergency(obs_.state)) obs_.alarm = false;
    return;
  }
  if (obs_.out_set_state == OutSetState::Emergency || !(obs_.resend || subsystem_not_emergency)) {
    obs_.resend = false;
    return;
  }
  if (obs_.set_age >= timing_.message_interval) {
    obs_.out_set_state = OutSetState::Emergency;
    obs_.set_age = 0;
    obs_.resend = false;
  } else {
    obs_.resend = true;
  }
}

CycleResult SafetyService::cycle(const InboundBatch& inbound, bool hardware_fault) noexcept {
  CycleResult result{};
  obs_.out_request = OutRequest::None;
  obs_.out_set_state = OutSetState::None;
  const ControlStatus control_before = obs_.control;
  const Intake in = intake(inbound);
  const ControlEvent ev = in.event;

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
  // A Confirm Control answers our pending Request Control; any other is ignored and counted.
  if ((ev == ControlEvent::Accepted || ev == ControlEvent::Refused) && control_before != ControlStatus::Requested) {
    ++diag_.unsolicited_confirm;
  }
  resend_step(in.subsystem_not_emergency);

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
