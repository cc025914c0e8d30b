#include "safestate/pro/protection_runtime.hpp"

namespace safestate::pro {

ProtectionRuntime::ProtectionRuntime(CommunicationsUnit& comms, RuntimeConfig config) noexcept
    : supervisor_(config.init_timeout_ticks),
      diagnostics_(data_),
      monitoring_(data_, config.sensor),
      control_(data_, config.tuning),
      safety_(data_, diagnostics_, config.limits),
      comms_(data_, comms) {}

ActiveObject& ProtectionRuntime::ao(AoId id) noexcept {
  switch (id) {
    case AoId::monitoring: return monitoring_;
    case AoId::control: return control_;
    case AoId::safety: return safety_;
    case AoId::diagnostics: return diagnostics_;
    case AoId::comms: break;
  }
  return comms_;
}

UnitStatus ProtectionRuntime::status(UnitId u) const noexcept {
  switch (u) {
    case UnitId::timer: return timer_.status();
    case UnitId::dispatcher: return dispatcher_status_;
    case UnitId::monitoring: return monitoring_.status();
    case UnitId::control: return control_.status();
    case UnitId::safety: return safety_.status();
    case UnitId::diagnostics: return diagnostics_.status();
    case UnitId::comms: break;
  }
  return comms_.status();
}

std::uint32_t ProtectionRuntime::overflow_count() const noexcept {
  return monitoring_.overflow_count() + control_.overflow_count() + safety_.overflow_count() +
         diagnostics_.overflow_count() + comms_.overflow_count() + safety_.unpublished() + lost_lifecycle_;
}

void ProtectionRuntime::post_counted(ActiveObject& target, const AoEvent& e) noexcept {
  if (target.post(e) != PostResult::ok) ++lost_lifecycle_;
}

// The lifecycle events of this tick's row (§7, §9), then every AO runs them to completion.
void ProtectionRuntime::deliver_lifecycle(const SupervisorStep& step) noexcept {
  const std::uint32_t now = data_.tick;
  if (step.entered_degraded || step.recovered) {
    const AoSignal sig = step.entered_degraded ? AoSignal::degraded : AoSignal::recovery;
    post_counted(control_, AoEvent{sig, now, 0, 0});
    post_counted(safety_, AoEvent{sig, now, 0, 0});
    post_counted(diagnostics_, AoEvent{sig, now, 0, 0});
    if (step.recovered) ++dispatcher_resets_;  // EVT_RESET to the dispatcher
  }
  if (step.stop_requested) {
    const StopStep& target = supervisor_.stop_target();
    if (target.outputs) {
      post_counted(control_, AoEvent{AoSignal::stop_outputs, now, 0, 0});
    } else if (target.unit == UnitId::timer) {
      timer_.stop();
    } else if (target.unit == UnitId::dispatcher) {
      dispatcher_status_ = UnitStatus::stopped;
    } else {
      post_counted(ao(static_cast<AoId>(static_cast<std::uint8_t>(target.unit) - 2)),
                   AoEvent{AoSignal::stop, now, 0, 0});
    }
  }
  for (const AoId id : kDispatchOrder) (void)ao(id).run_to_completion();
}

TickReport ProtectionRuntime::tick(const ControllerInputs& in) noexcept {
  TickReport report;
  if (supervisor_.state() == SupervisorState::stopped) {
    report.state = SupervisorState::stopped;
    report.tick = data_.tick;
    return report;
  }
  // Init: the first tick starts the timer, the dispatcher and every AO (§7).
  if (timer_.status() == UnitStatus::init) {
    timer_.start();
    dispatcher_status_ = UnitStatus::ready;
    for (const AoId id : kDispatchOrder) post_counted(ao(id), AoEvent{AoSignal::start, 0, 0, 0});
    for (const AoId id : kDispatchOrder) (void)ao(id).run_to_completion();
  }
  if (timer_.status() == UnitStatus::ready) data_.tick = timer_.advance();
  data_.sample = in.sample;
  data_.driver_fault = in.driver_fault;

  // 1. The units' reports and the fault inputs of this tick.
  control_.report_driver(in.driver_fault);
  comms_.sync_status();
  SupervisorInputs sin;
  for (std::size_t u = 0; u < kUnitCount; ++u) sin.status[u] = status(static_cast<UnitId>(u));
  sin.fatal_fault = in.fatal_fault;
  sin.watchdog_ok = in.watchdog_ok;
  sin.shutdown_requested = shutdown_requested_;
  sin.outputs_safe_reported = control_.outputs_safe();
  shutdown_requested_ = false;

  // 2. The supervisor's row.
  const SupervisorStep step = supervisor_.tick(sin);
  data_.supervisor = step.state;

  // 3. The dispatch cycle, fixed order, READY units as reported at the start of the tick.
  // Fail-safe defaults first: the snapshot mailbox is emptied (a safety unit that runs
  // without monitoring having run before it evaluates an invalid sensor, never an older
  // reading) and the output gate is closed (only ao_safety, on this tick's snapshot,
  // opens it); a tick in which safety does not run leaves the outputs safe.
  data_.snapshot = SensorSnapshot{};
  data_.fan_output = kSafeFanCommandPercent;
  data_.load_enable = false;
  report.dispatched = dispatch_cycle(
      dispatch_gate(step.mode, sin.status[index(UnitId::dispatcher)]),
      [&sin](AoId a) { return sin.status[index(unit_of(a))] == UnitStatus::ready; },
      [this](AoId a) {
        ActiveObject& target = ao(a);
        post_counted(target, AoEvent{AoSignal::tick, data_.tick, 0, 0});
        (void)target.run_to_completion();
      });

  // 4. The lifecycle events of the row, to every unit.
  deliver_lifecycle(step);

  report.tick = data_.tick;
  report.row = step.row;
  report.state = step.state;
  report.snapshot = data_.snapshot;
  report.safety_input = safety_input_of(report.dispatched);
  report.safety_ran = report.safety_input != SafetyInput::none;
  report.safety_result = data_.safety_result;
  report.fan_output = data_.fan_output;
  report.load_enable = data_.load_enable;
  report.stop_step = supervisor_.stop_step();
  return report;
}

}  // namespace safestate::pro
