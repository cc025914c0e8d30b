// SPDX-License-Identifier: Apache-2.0
// Flat switch-case re-implementation of docs/design/system-state-manager.md (§3, §5 rows
// C01-C26, §6 rows K01-K38, §7, §8). Row numbers are given in comments.
#include "switch_case_ssm.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace safestate_bench {

using safestate::AxisState;
using safestate::CommandKind;
using safestate::CommandResult;
using safestate::EnablePosition;
using safestate::FaultCode;
using safestate::OperatingMode;
using safestate::RejectReason;
using safestate::ResumeTarget;
using safestate::SelectorReading;
using safestate::SpeedLevel;
using safestate::StateId;
using safestate::StopCategory;

namespace {

std::uint32_t flat_count_mismatch(bool mismatch, std::uint32_t n, std::uint32_t d) noexcept {
  if (!mismatch) return 0;
  return n > d ? d + 1 : n + 1;  // min(n + 1, D + 1)
}

bool flat_same_mode(SelectorReading sel, OperatingMode mode) noexcept {
  switch (sel) {
    case SelectorReading::Auto: return mode == OperatingMode::Auto;
    case SelectorReading::T1: return mode == OperatingMode::T1;
    case SelectorReading::T2: return mode == OperatingMode::T2;
    case SelectorReading::Invalid: return false;
  }
  return false;
}

OperatingMode flat_mode_of(SelectorReading sel) noexcept {
  switch (sel) {
    case SelectorReading::Auto: return OperatingMode::Auto;
    case SelectorReading::T1: return OperatingMode::T1;
    case SelectorReading::T2: return OperatingMode::T2;
    case SelectorReading::Invalid: break;
  }
  return OperatingMode::None;
}

}  // namespace

SwitchCaseSsm::SwitchCaseSsm(const safestate::Config& config) noexcept
    : config_(config),
      kin_(config.dh),
      config_ok_(safestate::validate(config) == safestate::ConfigError::None),
      bus_(config.fieldbus_expected_working_counter, config.fieldbus_lost_cycles_limit),
      contactor_fb_(config.feedback_allowed_cycles),
      brake_fb_(config.feedback_allowed_cycles) {}

safestate::SubmitResult SwitchCaseSsm::submit(const safestate::Command& command) noexcept {
  if (queue_.size() >= config_.command_queue_limit || !queue_.try_push(command)) {
    status_.last_reject_reason = RejectReason::QueueFull;
    return safestate::SubmitResult::queue_full;
  }
  status_.queue_length = queue_.size();
  return safestate::SubmitResult::queued;
}

// Entering a state sets its data afresh (§4). Session mode survives only between powered
// states; STOPPING/HOLD data (category, resume target, jog) is set by the caller.
void SwitchCaseSsm::enter(StateId s) noexcept {
  const bool stays_powered = safestate::is_powered(s);
  state_ = s;
  state_cycles_ = 0;
  if (!stays_powered) session_ = OperatingMode::None;
  t2_confirmed_ = false;
  stopping_cat_ = StopCategory::None;
  resume_to_ = ResumeTarget::None;
  jog_axis_ = 0;
  jog_dir_ = 0;
  jog_speed_ = 0;
  fault_ = FaultCode::None;
}

void SwitchCaseSsm::lockout(FaultCode code) noexcept {
  enter(StateId::ErrorLockout);
  fault_ = code;
  status_.stop_category = StopCategory::Cat0;
}

void SwitchCaseSsm::stop(StopCategory cat) noexcept {  // -> STOPPING, CAT1 (CAT2 see K20)
  enter(StateId::Stopping);
  stopping_cat_ = cat;
  status_.stop_category = cat;
}

// K20 / C26: a Cat 2 stop that remembers the motion state; a paused jog keeps its setpoint.
void SwitchCaseSsm::pause() noexcept {
  const ResumeTarget r = state_ == StateId::AutoRunning ? ResumeTarget::AutoRunning : ResumeTarget::ManualJogging;
  const std::int32_t ja = jog_axis_;
  const std::int32_t jd = jog_dir_;
  const std::int32_t js = jog_speed_;
  stop(StopCategory::Cat2);
  resume_to_ = r;
  if (r == ResumeTarget::ManualJogging) {
    jog_axis_ = ja;
    jog_dir_ = jd;
    jog_speed_ = js;
  }
}

void SwitchCaseSsm::reject(RejectReason r) noexcept {
  status_.command_result = CommandResult::rejected(r);
  status_.last_reject_reason = r;
}

const safestate::ScanOutputs& SwitchCaseSsm::cycle(const safestate::ScanInputs& in) noexcept {
  // ---- §2 derived inputs ---------------------------------------------------------------
  const bool estop_tripped = !in.estop_closed.a || !in.estop_closed.b;
  const bool gate_open = !in.safeguard_closed.a || !in.safeguard_closed.b;
  const bool enable_middle = in.enabling.a == EnablePosition::Middle && in.enabling.b == EnablePosition::Middle;
  const bool enable_panic = in.enabling.a == EnablePosition::Panic || in.enabling.b == EnablePosition::Panic;
  const SelectorReading sel = in.selector.reading();
  // The drives' status words and the bus watchdog: the product's decoders (not under test here).
  const safestate::DriveStatusSummary drives = safestate::summarize_drives(in.bus.status_words);
  const bool fieldbus_ok = bus_.update(in.bus.cycle_counter, in.bus.working_counter);

  SpeedLevel speed = SpeedLevel::Zero;
  for (std::size_t i = 0; i < safestate::kAxisCount; ++i) {
    if (!(std::fabs(in.qd[i]) <= config_.zero_velocity_rad_s)) {
      speed = SpeedLevel::Moving;
      break;
    }
  }
  if (speed != SpeedLevel::Zero) {
    const double v = kin_.tcp_speed_mm_s(in.q, in.qd);
    if (!std::isfinite(v) || v > static_cast<double>(config_.t2_speed_limit_mm_s)) {
      speed = SpeedLevel::OverT2;
    } else if (v > static_cast<double>(config_.t1_speed_limit_mm_s)) {
      speed = SpeedLevel::OverT1;
    }
  }

  // ---- §3 channel monitoring -----------------------------------------------------------
  const std::uint32_t d = config_.discrepancy_cycles;
  estop_mm_ = flat_count_mismatch(in.estop_closed.a != in.estop_closed.b, estop_mm_, d);
  guard_mm_ = flat_count_mismatch(in.safeguard_closed.a != in.safeguard_closed.b, guard_mm_, d);
  enable_mm_ = flat_count_mismatch(in.enabling.a != in.enabling.b, enable_mm_, d);
  sel_inv_ = flat_count_mismatch(sel == SelectorReading::Invalid, sel_inv_, d);
  // K37: each E-stop channel seen open; K39: PANIC seen since both channels were RELEASED.
  estop_tested_a_ = estop_tested_a_ || !in.estop_closed.a;
  estop_tested_b_ = estop_tested_b_ || !in.estop_closed.b;
  enable_release_required_ = enable_panic || (enable_release_required_ && !(in.enabling.a == EnablePosition::Released &&
                                                                            in.enabling.b == EnablePosition::Released));
  // C30: each feedback against the output of the previous cycle (out_ still holds it).
  const bool contactor_bad =
      contactor_fb_.update(out_.contactor_closed, in.contactor_feedback_closed) != safestate::FeedbackFault::None;
  const bool brake_bad =
      brake_fb_.update(out_.brake_release, in.brake_feedback_released) != safestate::FeedbackFault::None;
  FaultCode discrepancy = FaultCode::None;
  if (estop_mm_ > d) {
    discrepancy = FaultCode::DiscrepancyEstop;
  } else if (guard_mm_ > d) {
    discrepancy = FaultCode::DiscrepancySafeguard;
  } else if (enable_mm_ > d) {
    discrepancy = FaultCode::DiscrepancyEnabling;
  } else if (sel_inv_ > d) {
    discrepancy = FaultCode::SelectorInvalid;
  }

  // ---- §5 safety evaluation, first matching row wins -----------------------------------
  const bool powered = safestate::is_powered(state_);
  const bool manual = session_ == OperatingMode::T1 || session_ == OperatingMode::T2;
  // C12-C14 hold off in STOPPING CAT1, and with the stop timer expired and the arm moving (C20).
  const bool stopping_cat1 =
      state_ == StateId::Stopping &&
      (stopping_cat_ == StopCategory::Cat1 || (state_cycles_ == config_.max_stop_cycles && speed != SpeedLevel::Zero));
  const StateId state_at_start = state_;
  const auto queued_at_start = static_cast<std::uint32_t>(queue_.size());

  if (state_ == StateId::ErrorLockout) {
    // C01: stay.
  } else if (state_ == StateId::Boot && !(in.self_test_ok && config_ok_)) {
    lockout(FaultCode::SelfTestFailed);  // C02
  } else if (discrepancy != FaultCode::None) {
    lockout(discrepancy);  // C03
  } else if (!fieldbus_ok) {
    lockout(FaultCode::FieldbusLoss);  // C24
  } else if (contactor_bad || brake_bad) {
    lockout(contactor_bad ? FaultCode::ContactorFeedback : FaultCode::BrakeFeedback);  // C30
  } else if (state_ == StateId::Boot) {
    if (estop_tripped) {
      enter(StateId::EstopActive);  // C04
      status_.stop_category = StopCategory::Cat0;
    } else {
      enter(StateId::Idle);  // C05
    }
  } else if (powered && drives.drive_fault) {
    lockout(FaultCode::DriveFault);  // C09
  } else if (powered && state_ != StateId::Arming && !drives.servo_ready) {
    lockout(FaultCode::ServoReadyLost);  // C27
  } else if (powered && session_ == OperatingMode::T1 && (speed == SpeedLevel::OverT1 || speed == SpeedLevel::OverT2)) {
    lockout(FaultCode::T1Overspeed);  // C10
  } else if (powered && session_ == OperatingMode::T2 && speed == SpeedLevel::OverT2) {
    lockout(FaultCode::T2Overspeed);  // C29
  } else if ((state_ == StateId::Arming || state_ == StateId::AutoIdle || state_ == StateId::ManualIdle ||
              state_ == StateId::Hold) &&
             speed != SpeedLevel::Zero) {
    lockout(FaultCode::StandstillViolation);  // C25
  } else if (state_ != StateId::EstopActive && estop_tripped) {
    enter(StateId::EstopActive);  // C06
    status_.stop_category = StopCategory::Cat0;
  } else if (state_ == StateId::EstopActive) {
    if (!estop_tripped) {
      enter(StateId::EstopResetNeeded);  // C07, else C08
      stale_commands_ = queued_at_start;
    }
  } else if (powered && manual && enable_panic) {
    enter(StateId::Idle);  // C11
    status_.stop_category = StopCategory::Cat0;
  } else if (powered && !stopping_cat1 &&
             (!flat_same_mode(sel, session_) ||                  // C12
              (session_ == OperatingMode::Auto && gate_open) ||  // C13
              (manual && !enable_middle))) {                     // C14
    // Escalating a Cat 2 stop in progress keeps its timer and counts the cycle; from ARMING
    // (nothing moves, brakes engaged) power is removed at once.
    const std::uint32_t kept = state_ == StateId::Stopping ? std::min(state_cycles_ + 1U, config_.max_stop_cycles) : 0U;
    if (state_ == StateId::Arming) {
      enter(StateId::Idle);
      status_.stop_category = StopCategory::Cat1;
    } else {
      stop(StopCategory::Cat1);
      state_cycles_ = kept;
    }
  } else if (state_ == StateId::ManualJogging && !in.operator_link_ok) {
    pause();  // C26: as a Pause (K20), the jog kept
  } else {
    switch (state_) {
      case StateId::Arming:
        if (drives.servo_ready) {
          enter(session_ == OperatingMode::Auto ? StateId::AutoIdle : StateId::ManualIdle);  // C15
        } else if (state_cycles_ == config_.arming_timeout_cycles) {
          lockout(FaultCode::ArmingTimeout);  // C16
        } else {
          ++state_cycles_;  // C17
        }
        break;
      case StateId::Stopping:
        if (speed == SpeedLevel::Zero && stopping_cat_ == StopCategory::Cat1) {
          enter(StateId::Idle);  // C18
        } else if (speed == SpeedLevel::Zero && stopping_cat_ == StopCategory::Cat2 &&
                   resume_to_ == ResumeTarget::None) {
          enter(StateId::ManualIdle);  // C28: the JOG_STOP's stop is done
        } else if (speed == SpeedLevel::Zero && stopping_cat_ == StopCategory::Cat2) {
          const ResumeTarget r = resume_to_;  // C19: HOLD keeps resume_to and jog
          const std::int32_t ja = jog_axis_;
          const std::int32_t jd = jog_dir_;
          const std::int32_t js = jog_speed_;
          enter(StateId::Hold);
          resume_to_ = r;
          jog_axis_ = ja;
          jog_dir_ = jd;
          jog_speed_ = js;
        } else if (state_cycles_ == config_.max_stop_cycles) {
          lockout(FaultCode::StopTimeout);  // C20
        } else {
          ++state_cycles_;  // C21
        }
        break;
      case StateId::Idle:
        if (sel != SelectorReading::T2 || (t2_confirmed_ && state_cycles_ == config_.t2_confirm_timeout_cycles)) {
          t2_confirmed_ = false;  // C22: off T2, or the confirmation expired
          state_cycles_ = 0;
        } else if (t2_confirmed_) {
          ++state_cycles_;  // C22: the confirmation ages
        }
        break;
      default: break;  // C23
    }
  }

  // ---- §6 at most one command ----------------------------------------------------------
  safestate::Command c;
  if (queue_.try_pop(c)) {
    handle_command(c, sel, gate_open, enable_middle, drives.drive_fault, state_at_start);
    if (stale_commands_ > 0) --stale_commands_;  // K36: one fewer command from before the release
  } else {
    status_.command_result = CommandResult::none();
  }

  // ---- §7 outputs, §8 axes --------------------------------------------------------------
  const bool pw = safestate::is_powered(state_);
  out_.contactor_closed = pw;
  out_.drive_enable = pw;
  out_.brake_release = pw && state_ != StateId::Arming;
  out_.ramp_down_request = state_ == StateId::Stopping;
  out_.reset_lamp = state_ == StateId::EstopResetNeeded;
  out_.commanded_speed_mm_s = state_ == StateId::ManualJogging ? jog_speed_ : 0;

  AxisState desired = AxisState::Disabled;
  switch (state_) {
    case StateId::ErrorLockout:
      desired = fault_ == FaultCode::DriveFault ? AxisState::ErrorStop : AxisState::Disabled;
      break;
    case StateId::AutoIdle:
    case StateId::ManualIdle:
    case StateId::Hold: desired = AxisState::StandStill; break;
    case StateId::AutoRunning: desired = AxisState::SynchronizedMotion; break;
    case StateId::ManualJogging:
      desired = AxisState::StandStill;  // ContinuousMotion for the jog axis, below
      break;
    case StateId::Stopping: desired = AxisState::Stopping; break;
    default: desired = AxisState::Disabled; break;
  }
  const bool speed_zero = speed == SpeedLevel::Zero;
  for (std::size_t i = 0; i < safestate::kAxisCount; ++i) {
    AxisState want = desired;
    if (state_ == StateId::ManualJogging && static_cast<std::size_t>(jog_axis_) == i + 1) {
      want = AxisState::ContinuousMotion;
    }
    axes_[i].track(want, speed_zero);
    out_.axes[i] = axes_[i].state();
  }

  // ---- status record -------------------------------------------------------------------
  status_.state = state_;
  status_.selector = sel;
  status_.session_mode = session_;
  status_.fault_code = fault_;
  status_.estop_mismatch = estop_mm_;
  status_.safeguard_mismatch = guard_mm_;
  status_.enabling_mismatch = enable_mm_;
  status_.selector_invalid = sel_inv_;
  status_.state_cycles = state_cycles_;
  status_.t2_confirmed = t2_confirmed_;
  status_.resume_to = resume_to_;
  status_.jog_axis = jog_axis_;
  status_.jog_direction = jog_dir_;
  status_.jog_speed_mm_s = jog_speed_;
  status_.queue_length = queue_.size();
  status_.stale_commands = stale_commands_;
  status_.estop_tested_a = estop_tested_a_;
  status_.estop_tested_b = estop_tested_b_;
  status_.enable_release_required = enable_release_required_;
  status_.contactor_fb_cycles = contactor_fb_.disagreeing_cycles();
  status_.brake_fb_cycles = brake_fb_.disagreeing_cycles();
  return out_;
}

void SwitchCaseSsm::handle_command(const safestate::Command& c, SelectorReading sel, bool gate_open, bool enable_middle,
                                   bool drive_fault, StateId state_at_start) noexcept {
  if (state_ == StateId::ErrorLockout) {
    reject(RejectReason::LockedOut);  // K01
    return;
  }
  const bool in_auto = sel == SelectorReading::Auto || session_ == OperatingMode::Auto;
  switch (c.kind) {
    case CommandKind::Reset:
      if (state_ == StateId::EstopActive) {
        reject(RejectReason::EstopPressed);  // K02
      } else if (stale_commands_ > 0) {
        reject(RejectReason::EstopPressed);  // K36
      } else if (state_ != StateId::EstopResetNeeded) {
        reject(RejectReason::WrongState);  // K03
      } else if (drive_fault) {
        reject(RejectReason::DriveFault);  // K04
      } else if (!(estop_tested_a_ && estop_tested_b_)) {
        reject(RejectReason::ChannelTestPending);  // K37
      } else {
        enter(StateId::Idle);  // K05
        estop_tested_a_ = false;
        estop_tested_b_ = false;
        status_.command_result = CommandResult::accepted();
      }
      return;
    case CommandKind::ServoOn:
      if (state_ != StateId::Idle) {
        reject(RejectReason::WrongState);  // K06
      } else if (state_at_start != StateId::Idle) {
        reject(RejectReason::WrongState);  // K38: IDLE entered in this cycle
      } else if (drive_fault) {
        reject(RejectReason::DriveFault);  // K07
      } else if (sel == SelectorReading::Invalid) {
        reject(RejectReason::SelectorInvalid);  // K08
      } else if (sel == SelectorReading::Auto && gate_open) {
        reject(RejectReason::SafeguardOpen);  // K09
      } else if ((sel == SelectorReading::T1 || sel == SelectorReading::T2) && !enable_middle) {
        reject(RejectReason::EnableNotMiddle);  // K10
      } else if ((sel == SelectorReading::T1 || sel == SelectorReading::T2) && enable_release_required_) {
        reject(RejectReason::EnableNotMiddle);  // K39: MIDDLE reached from PANIC
      } else if (sel == SelectorReading::T2 && !t2_confirmed_) {
        reject(RejectReason::T2NotConfirmed);  // K11
      } else {
        enter(StateId::Arming);  // K12
        session_ = flat_mode_of(sel);
        status_.stop_category = StopCategory::None;
        status_.command_result = CommandResult::accepted();
      }
      return;
    case CommandKind::ServoOff:
      switch (state_) {
        case StateId::Arming:
        case StateId::AutoIdle:
        case StateId::AutoRunning:
        case StateId::ManualIdle:
        case StateId::ManualJogging:
        case StateId::Hold:
          if (state_ == StateId::Arming) {
            enter(StateId::Idle);  // K14 from ARMING: nothing moves, power removed at once
            status_.stop_category = StopCategory::Cat1;
          } else {
            stop(StopCategory::Cat1);  // K14
          }
          status_.command_result = CommandResult::accepted();
          break;
        default:
          reject(RejectReason::WrongState);  // K13
          break;
      }
      return;
    case CommandKind::Start:
      if (state_ == StateId::ManualIdle || state_ == StateId::ManualJogging) {
        reject(RejectReason::WrongMode);  // K15
      } else if (state_ != StateId::AutoIdle) {
        reject(RejectReason::WrongState);  // K16
      } else if (gate_open) {
        reject(RejectReason::SafeguardOpen);  // K17
      } else {
        enter(StateId::AutoRunning);  // K18
        status_.command_result = CommandResult::accepted();
      }
      return;
    case CommandKind::Pause:
      if (state_ != StateId::AutoRunning && state_ != StateId::ManualJogging) {
        reject(RejectReason::WrongState);  // K19
      } else {
        pause();  // K20
        status_.command_result = CommandResult::accepted();
      }
      return;
    case CommandKind::Resume:
      if (state_ != StateId::Hold) {
        reject(RejectReason::WrongState);  // K21
      } else if (resume_to_ == ResumeTarget::AutoRunning && gate_open) {
        reject(RejectReason::SafeguardOpen);  // K22
      } else if (resume_to_ == ResumeTarget::ManualJogging && !enable_middle) {
        reject(RejectReason::EnableNotMiddle);  // K23
      } else {
        const bool jog = resume_to_ == ResumeTarget::ManualJogging;  // K24
        const std::int32_t ja = jog_axis_;
        const std::int32_t jd = jog_dir_;
        const std::int32_t js = jog_speed_;
        enter(jog ? StateId::ManualJogging : StateId::AutoRunning);
        if (jog) {
          jog_axis_ = ja;
          jog_dir_ = jd;
          jog_speed_ = js;
        }
        status_.command_result = CommandResult::accepted();
      }
      return;
    case CommandKind::JogStart:
      if (in_auto) {
        reject(RejectReason::JogInAuto);  // K25
      } else if (c.axis < 1 || c.axis > 6 || (c.direction != -1 && c.direction != 1) || c.speed_mm_s <= 0) {
        reject(RejectReason::InvalidArgument);  // K26
      } else if (state_ != StateId::ManualIdle) {
        reject(RejectReason::WrongState);  // K27
      } else if (!enable_middle) {
        reject(RejectReason::EnableNotMiddle);  // K28
      } else {
        enter(StateId::ManualJogging);  // K29
        jog_axis_ = c.axis;
        jog_dir_ = c.direction;
        jog_speed_ = session_ == OperatingMode::T1 && c.speed_mm_s > config_.t1_speed_limit_mm_s
                         ? config_.t1_speed_limit_mm_s
                         : c.speed_mm_s;
        status_.command_result = CommandResult::accepted();
      }
      return;
    case CommandKind::JogStop:
      if (in_auto) {
        reject(RejectReason::JogInAuto);  // K30
      } else if (state_ != StateId::ManualJogging) {
        reject(RejectReason::WrongState);  // K31
      } else {
        stop(StopCategory::Cat2);  // K32: a Cat 2 stop without resume target (C28)
        status_.command_result = CommandResult::accepted();
      }
      return;
    case CommandKind::T2Confirm:
      if (state_ != StateId::Idle) {
        reject(RejectReason::WrongState);  // K33
      } else if (sel != SelectorReading::T2) {
        reject(RejectReason::WrongMode);  // K34
      } else {
        t2_confirmed_ = true;  // K35
        state_cycles_ = 0;
        status_.command_result = CommandResult::accepted();
      }
      return;
  }
  reject(RejectReason::InvalidArgument);  // unknown command kind (not reachable via the enum)
}

}  // namespace safestate_bench
