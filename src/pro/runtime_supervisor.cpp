#include "safestate/pro/runtime_supervisor.hpp"

#include <algorithm>

namespace safestate::pro {

namespace {

bool all_are(const SupervisorInputs& in, UnitStatus s) {
  return std::all_of(in.status.begin(), in.status.end(), [s](UnitStatus u) { return u == s; });
}

bool fault(const SupervisorInputs& in) {
  const bool failed =
      std::any_of(in.status.begin(), in.status.end(), [](UnitStatus u) { return u == UnitStatus::failed; });
  return failed || in.fatal_fault || !in.watchdog_ok;
}

}  // namespace

bool RuntimeSupervisor::holds(SupervisorGuard g, const SupervisorInputs& in) const noexcept {
  switch (g) {
    case SupervisorGuard::shutdown_requested: return in.shutdown_requested;
    case SupervisorGuard::recovery_ok: return all_are(in, UnitStatus::ready) && !in.fatal_fault && in.watchdog_ok;
    case SupervisorGuard::fault: return fault(in);
    case SupervisorGuard::init_timeout: return init_ticks_ + 1 >= init_timeout_ticks_;
    case SupervisorGuard::all_stopped: return all_are(in, UnitStatus::stopped);
    case SupervisorGuard::always: break;
  }
  return true;
}

// A stop step is done when its unit reports (step 1: control reports the outputs safe);
// then the next one is requested. Only while shutting down, before this tick's rows.
void RuntimeSupervisor::advance_shutdown(const SupervisorInputs& in) noexcept {
  if (state_ != SupervisorState::shutting_down) return;
  const StopStep& step = stop_target();
  const bool done = step.outputs ? in.outputs_safe_reported : in.status[index(step.unit)] == UnitStatus::stopped;
  if (!done) return;
  if (step.outputs) outputs_safe_ = true;
  if (stop_step_ < kStopOrder.size()) ++stop_step_;
}

SupervisorStep RuntimeSupervisor::tick(const SupervisorInputs& in) noexcept {
  const SupervisorState before = state_;
  const std::uint8_t step_before = stop_step_;
  advance_shutdown(in);
  const SupervisorRow* fired = &kSupervisorRows.back();
  for (const SupervisorRow& r : kSupervisorRows) {
    if ((r.from & state_bit(before)) != 0 && holds(r.guard, in)) {
      fired = &r;
      break;
    }
  }
  if (!fired->stay) state_ = fired->target;
  init_ticks_ = fired->id == "I04" ? init_ticks_ + 1 : 0;
  if (fired->id == "X01") stop_step_ = 1;
  SupervisorStep out;
  out.row = fired;
  out.state = state_;
  out.mode = dispatch_mode(state_);
  out.entered_degraded = before != SupervisorState::degraded && state_ == SupervisorState::degraded;
  out.recovered = before == SupervisorState::degraded && state_ == SupervisorState::run;
  out.stop_requested = stop_step_ != step_before && state_ == SupervisorState::shutting_down;
  return out;
}

}  // namespace safestate::pro
