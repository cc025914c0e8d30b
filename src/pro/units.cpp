// The run-to-completion handlers of the five active objects (docs/design/protection.md
// §1-§4, §9). Each handles one event to its end; none blocks or allocates.
#include "safestate/pro/comms_ao.hpp"
#include "safestate/pro/control_ao.hpp"
#include "safestate/pro/diagnostics_ao.hpp"
#include "safestate/pro/monitoring_ao.hpp"
#include "safestate/pro/safety_ao.hpp"

namespace safestate::pro {

void MonitoringAo::on_event(const AoEvent& e) noexcept {
  if (handle_start_stop(e)) return;
  if (e.signal != AoSignal::tick) return;
  data_.snapshot = validator_.snapshot(data_.sample);
  // ao_safety_event.hazard_detected: the fan driver's fault line of this tick (§2).
  data_.snapshot.hazard_detected = data_.driver_fault;
  if (data_.clear_pending) {
    // A remote clear is a non-critical request: only in RUN (§8).
    if (data_.supervisor == SupervisorState::run) {
      data_.snapshot.clear_request = true;
    } else {
      data_.last_clear = ClearOutcome::refused;
    }
    data_.clear_pending = false;
  }
}

void ControlAo::report_driver(bool fault) noexcept {
  if (status() == UnitStatus::ready && fault) set_status(UnitStatus::failed);
  if (status() == UnitStatus::failed && !fault) set_status(UnitStatus::ready);
}

void ControlAo::on_event(const AoEvent& e) noexcept {
  if (handle_start_stop(e)) return;
  switch (e.signal) {
    case AoSignal::tick:
      if (outputs_safe_ || !data_.snapshot.sensor_valid) {
        data_.control_command = kSafeFanCommandPercent;  // no valid reading: full cooling
      } else {
        data_.control_command = pid_.step(data_.snapshot.temperature_c);
      }
      break;
    case AoSignal::stop_outputs:
      outputs_safe_ = true;
      data_.control_command = kSafeFanCommandPercent;
      data_.fan_output = kSafeFanCommandPercent;
      data_.load_enable = false;
      data_.outputs_held_safe = true;
      break;
    case AoSignal::degraded: ++degraded_; break;
    default: break;
  }
}

void SafetyAo::publish(const AoEvent& e) noexcept {
  if (diagnostics_.post(e) != PostResult::ok) ++unpublished_;
}

void SafetyAo::on_event(const AoEvent& e) noexcept {
  if (handle_start_stop(e)) return;
  if (e.signal == AoSignal::degraded || e.signal == AoSignal::recovery) {
    safety_.set_degraded(e.signal == AoSignal::degraded);
    return;
  }
  if (e.signal != AoSignal::tick) return;
  const SensorSnapshot& snap = data_.snapshot;
  data_.safety_result = safety_.dispatch(snap, e.tick);
  data_.fan_output = safety_.fan_output(data_.control_command);
  // After shutdown step 1 control holds the outputs safe; the permissive stays off.
  data_.load_enable = safety_.load_enable() && !data_.outputs_held_safe;
  if (snap.clear_request) {
    data_.last_clear =
        data_.safety_result == SafetyResult::latch_blocked ? ClearOutcome::denied : ClearOutcome::accepted;
  }
  const SafetyContext& ctx = safety_.context();
  publish(AoEvent{AoSignal::operating_status, e.tick, static_cast<std::uint8_t>(ctx.protection_state),
                  static_cast<std::uint8_t>(ctx.override_active ? 1 : 0)});
  if (safety_.last_fault_event() != FaultCause::none) {
    publish(AoEvent{AoSignal::fault_event, e.tick, static_cast<std::uint8_t>(safety_.last_fault_event()), 0});
  }
}

void DiagnosticsAo::on_event(const AoEvent& e) noexcept {
  ++counts_.events;
  if (handle_start_stop(e)) return;
  switch (e.signal) {
    case AoSignal::operating_status:
      published_ = static_cast<ProtectionState>(e.arg0);
      override_ = e.arg1 != 0;
      break;
    case AoSignal::fault_event:
      last_fault_ = static_cast<FaultCause>(e.arg0);
      if (e.arg0 < counts_.faults.size()) ++counts_.faults[e.arg0];
      break;
    case AoSignal::degraded: ++counts_.degraded; break;
    case AoSignal::recovery: ++counts_.recoveries; break;
    case AoSignal::tick: {
      ++counts_.ticks;
      ProcessImage& img = data_.image;
      img.temperature_c = data_.snapshot.temperature_c;
      img.voltage_dv = data_.snapshot.voltage_dv;
      img.fan_command_percent = data_.fan_output;
      img.protection_state = static_cast<std::uint16_t>(published_);
      img.supervisor_state = static_cast<std::uint16_t>(data_.supervisor);
      img.last_clear_result = static_cast<std::uint16_t>(data_.last_clear);
      img.latch_clear_request = data_.clear_pending ? 1 : 0;
      break;
    }
    default: break;
  }
}

void CommsAo::sync_status() noexcept {
  const UnitStatus s = unit_.status();
  if (status() != UnitStatus::init || s != UnitStatus::init) set_status(s);
}

void CommsAo::on_event(const AoEvent& e) noexcept {
  switch (e.signal) {
    case AoSignal::start: set_status(unit_.start()); break;
    case AoSignal::stop: set_status(unit_.stop()); break;
    case AoSignal::tick:
      data_.image.supervisor_state = static_cast<std::uint16_t>(data_.supervisor);
      unit_.on_tick(data_.image);
      if (unit_.take_requests().latch_clear_request) data_.clear_pending = true;
      break;
    default: break;
  }
}

}  // namespace safestate::pro
