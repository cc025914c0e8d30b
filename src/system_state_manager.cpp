// SPDX-License-Identifier: Apache-2.0
#include "safestate/system_state_manager.hpp"

#include <algorithm>

#include "safestate/step_context.hpp"
#include "safestate/transition_table.hpp"

namespace safestate {

namespace {

/// First row of the table that matches (first-match, design §5/§6). The table is total
/// (static_assert in transition_table.hpp), so a match always exists.
const TransitionRow& first_match(RowEvent event, const StepContext& ctx) noexcept {
  const StateId current = state_id(ctx.state);
  for (const TransitionRow& row : kTransitionTable) {
    const bool event_matches = row.event == event || (row.event == RowEvent::AnyCommand && event != RowEvent::Cycle);
    if (event_matches && row.source.contains(current) && row.guard(ctx)) {
      return row;
    }
  }
  return kTransitionTable[kCycleRowCount - 1];  // unreachable; C23 changes nothing
}

}  // namespace

SystemStateManager::SystemStateManager(const Config& config) noexcept
    : config_(config),
      config_error_(validate(config)),
      queue_limit_(std::min<std::size_t>(config.command_queue_limit, kMaxQueueCapacity)),
      speed_(config),
      estop_(config.discrepancy_cycles),
      safeguard_(config.discrepancy_cycles),
      enabling_(config.discrepancy_cycles),
      selector_(config.discrepancy_cycles),
      fieldbus_(config.fieldbus_expected_working_counter, config.fieldbus_lost_cycles_limit),
      contactor_fb_(config.feedback_allowed_cycles),
      brake_fb_(config.feedback_allowed_cycles) {}

SubmitResult SystemStateManager::submit(const Command& command) noexcept {
  // size() only shrinks under a concurrent consumer, so the limit check is conservative.
  if (queue_.size() >= queue_limit_ || !queue_.try_push(command)) {
    last_reject_reason_.store(RejectReason::QueueFull, std::memory_order_relaxed);
    return SubmitResult::queue_full;
  }
  return SubmitResult::queued;
}

void SystemStateManager::derive_inputs(const ScanInputs& in) noexcept {
  // §3: every counter, every cycle, in every state.
  estop_.update(in.estop_closed);
  safeguard_.update(in.safeguard_closed);
  enabling_.update(in.enabling);
  selector_.update(in.selector);

  DerivedInputs d;
  d.estop_tripped = estop_.tripped();
  d.gate_open = safeguard_.tripped();
  d.enable_middle = enabling_.both(EnablePosition::Middle);
  d.enable_panic = enabling_.either(EnablePosition::Panic);
  d.selector = selector_.reading();
  d.speed = speed_.classify(in.q, in.qd);
  d.self_test_ok = in.self_test_ok;
  // §2: the drives' CiA 402 status words and the bus watchdog, decoded here.
  drives_ = summarize_drives(in.bus.status_words);
  d.servo_ready = drives_.servo_ready;
  d.drive_fault = drives_.drive_fault;
  d.fieldbus_ok = fieldbus_.update(in.bus.cycle_counter, in.bus.working_counter);
  d.operator_link_ok = in.operator_link_ok;
  // C30: each feedback against the output the previous cycle wrote (state_ is still that
  // cycle's state here), every cycle, in every state.
  const ScanOutputs commanded = outputs();
  const bool contactor_bad =
      contactor_fb_.update(commanded.contactor_closed, in.contactor_feedback_closed) != FeedbackFault::None;
  const bool brake_bad = brake_fb_.update(commanded.brake_release, in.brake_feedback_released) != FeedbackFault::None;
  d.feedback = contactor_bad ? FaultCode::ContactorFeedback : brake_bad ? FaultCode::BrakeFeedback : FaultCode::None;
  // K39: PANIC on either channel latches; only RELEASED on both channels clears it.
  enable_release_required_ = enabling_.either(EnablePosition::Panic) ||
                             (enable_release_required_ && !enabling_.both(EnablePosition::Released));
  d.enable_release_required = enable_release_required_;
  // K37: an E-stop channel seen open, every cycle, in every state.
  reset_.estop_tested_a = reset_.estop_tested_a || !in.estop_closed.a;
  reset_.estop_tested_b = reset_.estop_tested_b || !in.estop_closed.b;
  // §3 order: E-stop, safeguard, enabling device, selector.
  if (estop_.discrepancy_fault()) {
    d.discrepancy = FaultCode::DiscrepancyEstop;
  } else if (safeguard_.discrepancy_fault()) {
    d.discrepancy = FaultCode::DiscrepancySafeguard;
  } else if (enabling_.discrepancy_fault()) {
    d.discrepancy = FaultCode::DiscrepancyEnabling;
  } else if (selector_.invalid_fault()) {
    d.discrepancy = FaultCode::SelectorInvalid;
  } else {
    d.discrepancy = FaultCode::None;
  }
  derived_ = d;
}

void SystemStateManager::fire(const TransitionRow& row, StepContext& ctx, bool is_command) noexcept {
  if (row.kind == TargetKind::Reject) {
    // RSM-13: a rejected command changes nothing but these two fields.
    command_result_ = CommandResult::rejected(row.reason);
    last_reject_reason_.store(row.reason, std::memory_order_relaxed);
    return;
  }
  row.action(ctx);
  switch (row.stop) {
    case StopUpdate::Keep: break;
    case StopUpdate::Cat0: stop_category_ = StopCategory::Cat0; break;
    case StopUpdate::Cat1: stop_category_ = StopCategory::Cat1; break;
    case StopUpdate::Cat2: stop_category_ = StopCategory::Cat2; break;
    case StopUpdate::Clear: stop_category_ = StopCategory::None; break;
  }
  if (is_command) {
    command_result_ = CommandResult::accepted();
  }
}

ScanOutputs SystemStateManager::cycle(const ScanInputs& inputs) noexcept {
  derive_inputs(inputs);
  StepContext ctx{state_,    derived_, config_,       config_error_ == ConfigError::None,
                  Command{}, reset_,   queue_.size(), state_id(state_)};

  // §5: safety evaluation, exactly one row.
  const TransitionRow& safety_row = first_match(RowEvent::Cycle, ctx);
  fire(safety_row, ctx, false);
  last_rows_.cycle = &safety_row;

  // §6: at most one command, validated against the state after §5.
  Command command;
  if (queue_.try_pop(command)) {
    ctx.command = command;
    const TransitionRow& command_row = first_match(event_of(command.kind), ctx);
    fire(command_row, ctx, true);
    last_rows_.command = &command_row;
    if (reset_.stale_commands > 0) {
      --reset_.stale_commands;  // K36: one fewer command from before the release
    }
  } else {
    command_result_ = CommandResult::none();
    last_rows_.command = nullptr;
  }

  // §8: one step of every axis toward what the new state wants.
  step_axes();
  return outputs();
}

AxisState desired_axis_state(const MachineState& s, std::size_t axis_index) noexcept {
  switch (state_id(s)) {
    case StateId::ErrorLockout:
      return fault_code(s) == FaultCode::DriveFault ? AxisState::ErrorStop : AxisState::Disabled;
    case StateId::AutoIdle:
    case StateId::ManualIdle:
    case StateId::Hold: return AxisState::StandStill;
    case StateId::AutoRunning: return AxisState::SynchronizedMotion;  // slaved to the path interpolator
    case StateId::ManualJogging: {
      const JogSetpoint j = jog(s);
      return static_cast<std::size_t>(j.axis) == axis_index + 1 ? AxisState::ContinuousMotion : AxisState::StandStill;
    }
    case StateId::Stopping: return AxisState::Stopping;
    case StateId::Boot:
    case StateId::Idle:
    case StateId::EstopActive:
    case StateId::EstopResetNeeded:
    case StateId::Arming: return AxisState::Disabled;
  }
  return AxisState::Disabled;
}

void SystemStateManager::step_axes() noexcept {
  const bool speed_zero = derived_.speed == SpeedLevel::Zero;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    axes_[i].track(desired_axis_state(state_, i), speed_zero);
  }
}

ScanOutputs SystemStateManager::outputs() const noexcept {
  const StateId s = state_id(state_);
  ScanOutputs out;
  out.contactor_closed = is_powered(s);
  out.drive_enable = is_powered(s);
  // Contactor and drive enable from ARMING on, the brakes only once the drives reported
  // ready (C15): contactor -> servo on -> brake release (issue 29 item 2).
  out.brake_release = is_powered(s) && s != StateId::Arming;
  out.ramp_down_request = s == StateId::Stopping;
  out.reset_lamp = s == StateId::EstopResetNeeded;
  out.commanded_speed_mm_s = s == StateId::ManualJogging ? jog(state_).speed_mm_s : 0;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    out.axes[i] = axes_[i].state();
  }
  return out;
}

StatusRecord SystemStateManager::status() const noexcept {
  StatusRecord r;
  r.state = state_id(state_);
  r.selector = selector_.reading();
  r.session_mode = session_mode(state_);
  r.stop_category = stop_category_;
  r.fault_code = fault_code(state_);
  r.last_reject_reason = last_reject_reason_.load(std::memory_order_relaxed);
  r.command_result = command_result_;
  r.estop_mismatch = estop_.mismatch_cycles();
  r.safeguard_mismatch = safeguard_.mismatch_cycles();
  r.enabling_mismatch = enabling_.mismatch_cycles();
  r.selector_invalid = selector_.invalid_cycles();
  r.state_cycles = state_cycles(state_);
  r.t2_confirmed = t2_confirmed(state_);
  r.resume_to = resume_to(state_);
  const JogSetpoint j = jog(state_);
  r.jog_axis = j.axis;
  r.jog_direction = j.direction;
  r.jog_speed_mm_s = j.speed_mm_s;
  r.queue_length = queue_.size();
  r.stale_commands = reset_.stale_commands;
  r.estop_tested_a = reset_.estop_tested_a;
  r.estop_tested_b = reset_.estop_tested_b;
  r.enable_release_required = enable_release_required_;
  r.contactor_fb_cycles = contactor_fb_.disagreeing_cycles();
  r.brake_fb_cycles = brake_fb_.disagreeing_cycles();
  return r;
}

}  // namespace safestate
