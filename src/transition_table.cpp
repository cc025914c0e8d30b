// SPDX-License-Identifier: Apache-2.0
// Guards and actions named by the transition table (include/safestate/transition_table.hpp).
// Each is a one-liner so that it can be checked against the design page's wording.
#include "safestate/transition_table.hpp"

#include <algorithm>

#include "safestate/step_context.hpp"

namespace safestate {

namespace {

// C12-C14 do not fire in STOPPING with CAT1 (already the stop asked for) nor with the stop
// timer expired and the arm still moving (C20 cuts power: Cat 0 beats an escalation).
bool stopping_cat1(const StepContext& c) noexcept {
  return stopping_category(c.state) == StopCategory::Cat1 ||
         (state_id(c.state) == StateId::Stopping && state_cycles(c.state) == c.config.max_stop_cycles &&
          c.in.speed != SpeedLevel::Zero);
}

}  // namespace

namespace guards {

bool always(const StepContext&) noexcept { return true; }

// C02: a failed platform self-test, or a Config that validate() refuses.
bool self_test_failed_or_config_invalid(const StepContext& c) noexcept { return !c.in.self_test_ok || !c.config_valid; }

// C03: a counter of §3 above D.
bool discrepancy_fault(const StepContext& c) noexcept { return c.in.discrepancy != FaultCode::None; }

bool estop_tripped(const StepContext& c) noexcept { return c.in.estop_tripped; }
bool estop_released(const StepContext& c) noexcept { return !c.in.estop_tripped; }
bool drive_fault(const StepContext& c) noexcept { return c.in.drive_fault; }

// C10: session_mode = T1 ∧ speed ∈ {OVER_T1, OVER_T2}.
bool t1_session_overspeed(const StepContext& c) noexcept {
  return session_mode(c.state) == OperatingMode::T1 &&
         (c.in.speed == SpeedLevel::OverT1 || c.in.speed == SpeedLevel::OverT2);
}

// C29: session_mode = T2 ∧ speed = OVER_T2 (issue 29 item 5).
bool t2_session_overspeed(const StepContext& c) noexcept {
  return session_mode(c.state) == OperatingMode::T2 && c.in.speed == SpeedLevel::OverT2;
}

// C11: manual ∧ enable_panic.
bool manual_session_panic(const StepContext& c) noexcept {
  return is_manual(session_mode(c.state)) && c.in.enable_panic;
}

// C12: not (STOPPING with CAT1 or timer expired) ∧ selector ≠ session_mode (a change, or INVALID).
bool selector_differs_from_session_unless_cat1_stopping(const StepContext& c) noexcept {
  return !stopping_cat1(c) && !selector_matches(c.in.selector, session_mode(c.state));
}

// C13: not (STOPPING with CAT1 or timer expired) ∧ session_mode = AUTO ∧ gate_open.
bool auto_session_gate_open_unless_cat1_stopping(const StepContext& c) noexcept {
  return !stopping_cat1(c) && session_mode(c.state) == OperatingMode::Auto && c.in.gate_open;
}

// C14: not (STOPPING with CAT1 or timer expired) ∧ manual ∧ ¬enable_middle.
bool manual_session_enable_not_middle_unless_cat1_stopping(const StepContext& c) noexcept {
  return !stopping_cat1(c) && is_manual(session_mode(c.state)) && !c.in.enable_middle;
}

bool servo_ready(const StepContext& c) noexcept { return c.in.servo_ready; }

// C16: the drives had arming_timeout_cycles full cycles after the Servo-on cycle.
bool arming_timer_expired(const StepContext& c) noexcept {
  return state_cycles(c.state) == c.config.arming_timeout_cycles;
}

// C18 / C19: measured standstill ends the stop of that category.
bool stopped_cat1(const StepContext& c) noexcept {
  return c.in.speed == SpeedLevel::Zero && stopping_category(c.state) == StopCategory::Cat1;
}
bool stopped_cat2(const StepContext& c) noexcept {
  return c.in.speed == SpeedLevel::Zero && stopping_category(c.state) == StopCategory::Cat2;
}

// C20: the robot had max_stop_cycles full cycles to stop.
bool stop_timer_expired(const StepContext& c) noexcept { return state_cycles(c.state) == c.config.max_stop_cycles; }

bool selector_not_t2(const StepContext& c) noexcept { return c.in.selector != SelectorReading::T2; }
// C22: the T2 confirmation is cleared when the selector leaves T2 and ages while it holds.
bool selector_not_t2_or_t2_confirmed(const StepContext& c) noexcept {
  return c.in.selector != SelectorReading::T2 || t2_confirmed(c.state);
}
bool selector_invalid(const StepContext& c) noexcept { return c.in.selector == SelectorReading::Invalid; }

bool selector_auto_and_gate_open(const StepContext& c) noexcept {
  return c.in.selector == SelectorReading::Auto && c.in.gate_open;
}

bool selector_manual_and_enable_not_middle(const StepContext& c) noexcept {
  return (c.in.selector == SelectorReading::T1 || c.in.selector == SelectorReading::T2) && !c.in.enable_middle;
}

bool selector_t2_and_not_confirmed(const StepContext& c) noexcept {
  return c.in.selector == SelectorReading::T2 && !t2_confirmed(c.state);
}

bool gate_open(const StepContext& c) noexcept { return c.in.gate_open; }

bool resume_to_auto_and_gate_open(const StepContext& c) noexcept {
  return resume_to(c.state) == ResumeTarget::AutoRunning && c.in.gate_open;
}

bool resume_to_jog_and_enable_not_middle(const StepContext& c) noexcept {
  return resume_to(c.state) == ResumeTarget::ManualJogging && !c.in.enable_middle;
}

// §6: "in AUTO" means selector = AUTO ∨ session_mode = AUTO.
bool in_auto(const StepContext& c) noexcept {
  return c.in.selector == SelectorReading::Auto || session_mode(c.state) == OperatingMode::Auto;
}

// K26: axis ∉ 1..6 ∨ dir ∉ {-1, 1} ∨ speed ≤ 0 ∨ speed > t2_speed_limit_mm_s.
bool jog_arguments_invalid(const StepContext& c) noexcept {
  const Command& k = c.command;
  return k.axis < 1 || k.axis > 6 || (k.direction != -1 && k.direction != 1) || k.speed_mm_s <= 0 ||
         k.speed_mm_s > c.config.t2_speed_limit_mm_s;
}

bool enable_not_middle(const StepContext& c) noexcept { return !c.in.enable_middle; }

// C30: a feedback monitor latched (the contactor or the brakes did not follow their command).
bool feedback_fault(const StepContext& c) noexcept { return c.in.feedback != FaultCode::None; }

// C24: the fieldbus (EtherCAT) or the cycle watchdog reports a loss.
bool fieldbus_lost(const StepContext& c) noexcept { return !c.in.fieldbus_ok; }

// C26: the controlling operator client's heartbeat did not arrive within its period.
bool operator_link_lost(const StepContext& c) noexcept { return !c.in.operator_link_ok; }

// C25: power on, no motion commanded (the row's source states), measured motion. No axis is
// exempt: every stop reaches these states only in a cycle that measured standstill.
bool moving_at_standstill(const StepContext& c) noexcept { return c.in.speed != SpeedLevel::Zero; }

// C27: the drives no longer report ready (the row's source: the brakes are released).
bool servo_not_ready(const StepContext& c) noexcept { return !c.in.servo_ready; }

// C28: a JOG_STOP's Cat 2 stop (no resume target) has reached standstill.
bool stopped_jog_stop(const StepContext& c) noexcept {
  return c.in.speed == SpeedLevel::Zero && stopping_category(c.state) == StopCategory::Cat2 &&
         resume_to(c.state) == ResumeTarget::None;
}

// K39: the enabling device reached MIDDLE from PANIC without RELEASED (ISO 10218-1 5.8.3).
bool selector_manual_and_enable_release_required(const StepContext& c) noexcept {
  return (c.in.selector == SelectorReading::T1 || c.in.selector == SelectorReading::T2) && c.in.enable_release_required;
}

// K36: the Reset was queued before the E-stop release (C07 counted it as stale).
bool reset_submitted_before_release(const StepContext& c) noexcept { return c.reset.stale_commands > 0; }

// K37: not both E-stop channels seen open since the last accepted Reset.
bool estop_channels_not_both_tested(const StepContext& c) noexcept {
  return !(c.reset.estop_tested_a && c.reset.estop_tested_b);
}

// K38: IDLE only since this cycle's §5 row (C05, C11, C18): power was never seen off.
bool not_idle_at_cycle_start(const StepContext& c) noexcept { return c.cycle_start_state != StateId::Idle; }

}  // namespace guards

namespace actions {

void none(StepContext&) noexcept {}

void lockout_self_test_failed(StepContext& c) noexcept { c.state = states::ErrorLockout{FaultCode::SelfTestFailed}; }
void lockout_discrepancy(StepContext& c) noexcept { c.state = states::ErrorLockout{c.in.discrepancy}; }
void lockout_drive_fault(StepContext& c) noexcept { c.state = states::ErrorLockout{FaultCode::DriveFault}; }
void lockout_t1_overspeed(StepContext& c) noexcept { c.state = states::ErrorLockout{FaultCode::T1Overspeed}; }
void lockout_t2_overspeed(StepContext& c) noexcept { c.state = states::ErrorLockout{FaultCode::T2Overspeed}; }
void lockout_arming_timeout(StepContext& c) noexcept { c.state = states::ErrorLockout{FaultCode::ArmingTimeout}; }
void lockout_stop_timeout(StepContext& c) noexcept { c.state = states::ErrorLockout{FaultCode::StopTimeout}; }
void lockout_fieldbus_loss(StepContext& c) noexcept { c.state = states::ErrorLockout{FaultCode::FieldbusLoss}; }
void lockout_feedback(StepContext& c) noexcept { c.state = states::ErrorLockout{c.in.feedback}; }
void lockout_standstill_violation(StepContext& c) noexcept {
  c.state = states::ErrorLockout{FaultCode::StandstillViolation};
}
void lockout_servo_ready_lost(StepContext& c) noexcept { c.state = states::ErrorLockout{FaultCode::ServoReadyLost}; }

void enter_estop_active(StepContext& c) noexcept { c.state = states::EstopActive{}; }
// C07: every command queued now was submitted before the release (K36).
void enter_estop_reset_needed(StepContext& c) noexcept {
  c.state = states::EstopResetNeeded{};
  c.reset.stale_commands = static_cast<std::uint32_t>(c.queued_commands);
}

// Entering IDLE sets t2_confirmed FALSE (§4).
void enter_idle(StepContext& c) noexcept { c.state = states::Idle{false}; }

// K05: the accepted Reset starts a new channel test (K37).
void reset_to_idle(StepContext& c) noexcept {
  enter_idle(c);
  c.reset.estop_tested_a = false;
  c.reset.estop_tested_b = false;
}

// Cat 1: ramp down with power kept; no resume target, no jog (§4). Escalating a stop in
// progress (STOPPING CAT2) keeps its timer and counts the cycle (as C21): the watchdog
// runs from the first trigger (C12-C14 never fire with the timer expired). From ARMING
// (brakes engaged, drives not ready, nothing moves) the stop is complete at once: IDLE.
void enter_stopping_cat1(StepContext& c) noexcept {
  if (state_id(c.state) == StateId::Arming) {
    enter_idle(c);
    return;
  }
  const std::uint32_t kept =
      state_id(c.state) == StateId::Stopping ? std::min(state_cycles(c.state) + 1U, c.config.max_stop_cycles) : 0U;
  c.state = states::Stopping{session_mode(c.state), StopCategory::Cat1, kept, ResumeTarget::None, JogSetpoint{}};
}

// K20 Pause: Cat 2, remembers the motion state; a paused jog keeps its setpoint.
void enter_stopping_cat2_pause(StepContext& c) noexcept {
  const bool jogging = state_id(c.state) == StateId::ManualJogging;
  c.state = states::Stopping{session_mode(c.state), StopCategory::Cat2, 0,
                             jogging ? ResumeTarget::ManualJogging : ResumeTarget::AutoRunning,
                             jogging ? jog(c.state) : JogSetpoint{}};
}

// C15: the OPERATIONAL sub-state of the session's mode.
void enter_operational_idle(StepContext& c) noexcept {
  const OperatingMode mode = session_mode(c.state);
  if (mode == OperatingMode::Auto) {
    c.state = states::AutoIdle{};
  } else {
    c.state = states::ManualIdle{mode};
  }
}

// C19: HOLD keeps resume_to and jog.
void enter_hold(StepContext& c) noexcept {
  c.state = states::Hold{session_mode(c.state), resume_to(c.state), jog(c.state)};
}

// C17 / C21: one more cycle in ARMING / STOPPING.
void count_state_cycle(StepContext& c) noexcept {
  if (auto* a = std::get_if<states::Arming>(&c.state)) {
    ++a->state_cycles;
  } else if (auto* s = std::get_if<states::Stopping>(&c.state)) {
    ++s->state_cycles;
  }
}

// C22: selector off T2, or the confirmation t2_confirm_timeout_cycles old: cleared; else one
// cycle older. A Servo-on is accepted for t2_confirm_timeout_cycles cycles after K35's.
void age_t2_confirmation(StepContext& c) noexcept {
  if (auto* idle = std::get_if<states::Idle>(&c.state)) {
    if (c.in.selector != SelectorReading::T2 || idle->state_cycles == c.config.t2_confirm_timeout_cycles) {
      *idle = states::Idle{false, 0};
    } else {
      ++idle->state_cycles;
    }
  }
}

// K12: session_mode := selector (stop_category := NONE is the row's StopUpdate::Clear).
void enter_arming(StepContext& c) noexcept { c.state = states::Arming{mode_of(c.in.selector), 0}; }

void enter_auto_running(StepContext& c) noexcept { c.state = states::AutoRunning{}; }

// K24: back to resume_to, with its jog.
void resume_motion(StepContext& c) noexcept {
  if (resume_to(c.state) == ResumeTarget::ManualJogging) {
    c.state = states::ManualJogging{session_mode(c.state), jog(c.state)};
  } else {
    c.state = states::AutoRunning{};
  }
}

// K29: the commanded speed is clamped to the T1 limit in T1 (RSM-10, INV-T1SPEED).
void start_jog(StepContext& c) noexcept {
  const OperatingMode mode = session_mode(c.state);
  const std::int32_t speed =
      mode == OperatingMode::T1 ? std::min(c.command.speed_mm_s, c.config.t1_speed_limit_mm_s) : c.command.speed_mm_s;
  c.state = states::ManualJogging{mode, JogSetpoint{c.command.axis, c.command.direction, speed}};
}

// K32: a JOG_STOP is a Cat 2 stop: ramp-down requested, stop timer running (C20), no resume
// target, so that C28 ends it in MANUAL_IDLE at standstill (issue 29 item 1).
void enter_stopping_cat2_jog_stop(StepContext& c) noexcept {
  c.state = states::Stopping{session_mode(c.state), StopCategory::Cat2, 0, ResumeTarget::None, JogSetpoint{}};
}

// C28: the jog stop reached standstill.
void enter_manual_idle(StepContext& c) noexcept { c.state = states::ManualIdle{session_mode(c.state)}; }

// K35: a (new) confirmation, valid from now for t2_confirm_timeout_cycles cycles (C22).
void confirm_t2(StepContext& c) noexcept {
  if (auto* idle = std::get_if<states::Idle>(&c.state)) *idle = states::Idle{true, 0};
}

}  // namespace actions

}  // namespace safestate
