// SPDX-License-Identifier: Apache-2.0
// THE transition table of the SystemStateManager: design §5 (rows C01–C23, one scan cycle)
// and §6 (rows K01–K35, one command), in the page's order, evaluated first-match.
//
// Reading a row: in a state of `source`, on `event`, if `guard` holds, the row fires:
//   enter(T, action)  - the action constructs state T afresh (T may be a choice, e.g. C15)
//   stay(action)      - the state is kept; the action may update its data
//   reject(REASON)    - commands only: nothing changes but command_result/last_reject_reason
// `stop` is what the row writes into the status field stop_category (§7).
//
// Where the page writes a state condition as a guard ("state ≠ IDLE"), the table puts it
// into `source` (all states but IDLE) and the guard is `always`: first-match evaluation is
// the same. Guards and actions are the named functions in transition_table.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <string_view>

#include "safestate/state_set.hpp"
#include "safestate/transition_row.hpp"

namespace safestate {

/// Guards: pure functions of the state and the cycle's derived inputs (and the command).
namespace guards {
bool always(const StepContext&) noexcept;
bool self_test_failed_or_config_invalid(const StepContext&) noexcept;
bool discrepancy_fault(const StepContext&) noexcept;
bool estop_tripped(const StepContext&) noexcept;
bool estop_released(const StepContext&) noexcept;
bool drive_fault(const StepContext&) noexcept;
bool t1_session_overspeed(const StepContext&) noexcept;
bool t2_session_overspeed(const StepContext&) noexcept;
bool manual_session_panic(const StepContext&) noexcept;
bool selector_differs_from_session_unless_cat1_stopping(const StepContext&) noexcept;
bool auto_session_gate_open_unless_cat1_stopping(const StepContext&) noexcept;
bool manual_session_enable_not_middle_unless_cat1_stopping(const StepContext&) noexcept;
bool servo_ready(const StepContext&) noexcept;
bool arming_timer_expired(const StepContext&) noexcept;
bool stopped_cat1(const StepContext&) noexcept;
bool stopped_cat2(const StepContext&) noexcept;
bool stop_timer_expired(const StepContext&) noexcept;
bool selector_not_t2(const StepContext&) noexcept;
bool selector_not_t2_or_t2_confirmed(const StepContext&) noexcept;
bool selector_invalid(const StepContext&) noexcept;
bool selector_auto_and_gate_open(const StepContext&) noexcept;
bool selector_manual_and_enable_not_middle(const StepContext&) noexcept;
bool selector_t2_and_not_confirmed(const StepContext&) noexcept;
bool gate_open(const StepContext&) noexcept;
bool resume_to_auto_and_gate_open(const StepContext&) noexcept;
bool resume_to_jog_and_enable_not_middle(const StepContext&) noexcept;
bool in_auto(const StepContext&) noexcept;
bool jog_arguments_invalid(const StepContext&) noexcept;
bool enable_not_middle(const StepContext&) noexcept;
bool fieldbus_lost(const StepContext&) noexcept;
bool feedback_fault(const StepContext&) noexcept;
bool operator_link_lost(const StepContext&) noexcept;
bool moving_at_standstill(const StepContext&) noexcept;
bool reset_submitted_before_release(const StepContext&) noexcept;
bool estop_channels_not_both_tested(const StepContext&) noexcept;
bool not_idle_at_cycle_start(const StepContext&) noexcept;
bool servo_not_ready(const StepContext&) noexcept;
bool stopped_jog_stop(const StepContext&) noexcept;
bool selector_manual_and_enable_release_required(const StepContext&) noexcept;
}  // namespace guards

/// Actions: construct the entered state (with its §4 data) or update the current one.
namespace actions {
void none(StepContext&) noexcept;
void lockout_self_test_failed(StepContext&) noexcept;
void lockout_discrepancy(StepContext&) noexcept;
void lockout_drive_fault(StepContext&) noexcept;
void lockout_t1_overspeed(StepContext&) noexcept;
void lockout_t2_overspeed(StepContext&) noexcept;
void lockout_arming_timeout(StepContext&) noexcept;
void lockout_stop_timeout(StepContext&) noexcept;
void lockout_fieldbus_loss(StepContext&) noexcept;
void lockout_feedback(StepContext&) noexcept;
void lockout_standstill_violation(StepContext&) noexcept;
void reset_to_idle(StepContext&) noexcept;
void enter_estop_active(StepContext&) noexcept;
void enter_estop_reset_needed(StepContext&) noexcept;
void enter_idle(StepContext&) noexcept;
void enter_stopping_cat1(StepContext&) noexcept;
void enter_stopping_cat2_pause(StepContext&) noexcept;
void enter_operational_idle(StepContext&) noexcept;
void enter_hold(StepContext&) noexcept;
void count_state_cycle(StepContext&) noexcept;
void age_t2_confirmation(StepContext&) noexcept;
void enter_arming(StepContext&) noexcept;
void enter_auto_running(StepContext&) noexcept;
void resume_motion(StepContext&) noexcept;
void start_jog(StepContext&) noexcept;
void confirm_t2(StepContext&) noexcept;
void lockout_servo_ready_lost(StepContext&) noexcept;
void enter_stopping_cat2_jog_stop(StepContext&) noexcept;
void enter_manual_idle(StepContext&) noexcept;
}  // namespace actions

namespace table_dsl {

using St = StateId;
using Ev = RowEvent;
using Why = RejectReason;
using Stop = StopUpdate;

struct Effect {
  TargetKind kind;
  StateSet targets;
  RejectReason reason;
  ActionFn action;
  std::string_view action_name;
};

[[nodiscard]] constexpr Effect enter(StateSet targets, ActionFn action, std::string_view name) noexcept {
  return {TargetKind::Enter, targets, RejectReason::None, action, name};
}
[[nodiscard]] constexpr Effect stay(ActionFn action, std::string_view name) noexcept {
  return {TargetKind::Stay, StateSet{}, RejectReason::None, action, name};
}
[[nodiscard]] constexpr Effect reject(RejectReason reason) noexcept {
  return {TargetKind::Reject, StateSet{}, reason, &actions::none, "none"};
}

[[nodiscard]] constexpr TransitionRow row(std::string_view id, RowEvent event, StateSet source, GuardFn guard,
                                          std::string_view guard_name, Effect effect, StopUpdate stop,
                                          std::string_view requirements) noexcept {
  return {id,
          event,
          source,
          guard,
          guard_name,
          effect.kind,
          effect.targets,
          effect.reason,
          stop,
          effect.action,
          effect.action_name,
          requirements};
}

[[nodiscard]] constexpr StateSet any() noexcept { return StateSet::all(); }
[[nodiscard]] constexpr StateSet any_but(std::initializer_list<StateId> s) noexcept { return StateSet::all_except(s); }
[[nodiscard]] constexpr StateSet powered() noexcept { return StateSet::powered(); }

// Name and address of a guard/action in one go, so the exported name cannot drift.
#define SAFESTATE_GUARD(fn) &::safestate::guards::fn, #fn
#define SAFESTATE_ACTION(fn) &::safestate::actions::fn, #fn

// clang-format off
inline constexpr std::array<TransitionRow, 69> kRows{{
  // ---- §5: one scan cycle, after channel monitoring (§3) ---------------------------------------
  // id     event      source                    guard                                                              effect                                                                       stop        requirements
  row("C01", Ev::Cycle, {St::ErrorLockout},       SAFESTATE_GUARD(always),                                          stay(SAFESTATE_ACTION(none)),                                                Stop::Keep, "RSM-04, INV-DISCREPANCY"),
  row("C02", Ev::Cycle, {St::Boot},               SAFESTATE_GUARD(self_test_failed_or_config_invalid),              enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_self_test_failed)),       Stop::Cat0, "RSM-12"),
  row("C03", Ev::Cycle, any(),                    SAFESTATE_GUARD(discrepancy_fault),                               enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_discrepancy)),            Stop::Cat0, "RSM-04, RSM-02"),
  row("C24", Ev::Cycle, any(),                    SAFESTATE_GUARD(fieldbus_lost),                                   enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_fieldbus_loss)),          Stop::Cat0, "RSM-03, seed"),
  row("C30", Ev::Cycle, any(),                    SAFESTATE_GUARD(feedback_fault),                                  enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_feedback)),               Stop::Cat0, "RSM-03, RSM-07, UCA-RSM-13"),
  row("C04", Ev::Cycle, {St::Boot},               SAFESTATE_GUARD(estop_tripped),                                   enter({St::EstopActive}, SAFESTATE_ACTION(enter_estop_active)),              Stop::Cat0, "RSM-12"),
  row("C05", Ev::Cycle, {St::Boot},               SAFESTATE_GUARD(always),                                          enter({St::Idle}, SAFESTATE_ACTION(enter_idle)),                             Stop::Keep, "RSM-12"),
  // The latching rows before C06: an E-stop in the same cycle keeps the lockout (issue 29 item 7).
  row("C09", Ev::Cycle, powered(),                SAFESTATE_GUARD(drive_fault),                                     enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_drive_fault)),            Stop::Cat0, "RSM-07, RSM-03"),
  row("C27", Ev::Cycle, {St::AutoIdle, St::AutoRunning, St::ManualIdle, St::ManualJogging, St::Stopping, St::Hold},
                                                  SAFESTATE_GUARD(servo_not_ready),                                 enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_servo_ready_lost)),       Stop::Cat0, "RSM-07, RSM-03"),
  row("C10", Ev::Cycle, powered(),                SAFESTATE_GUARD(t1_session_overspeed),                            enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_t1_overspeed)),           Stop::Cat0, "RSM-10, INV-T1SPEED"),
  row("C29", Ev::Cycle, powered(),                SAFESTATE_GUARD(t2_session_overspeed),                            enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_t2_overspeed)),           Stop::Cat0, "RSM-10, RSM-03, UCA-RSM-12"),
  row("C25", Ev::Cycle, {St::Arming, St::AutoIdle, St::ManualIdle, St::Hold}, SAFESTATE_GUARD(moving_at_standstill), enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_standstill_violation)), Stop::Cat0, "RSM-11, RSM-03"),
  row("C06", Ev::Cycle, any_but({St::EstopActive}), SAFESTATE_GUARD(estop_tripped),                                 enter({St::EstopActive}, SAFESTATE_ACTION(enter_estop_active)),              Stop::Cat0, "RSM-05, INV-1OO2"),
  row("C07", Ev::Cycle, {St::EstopActive},        SAFESTATE_GUARD(estop_released),                                  enter({St::EstopResetNeeded}, SAFESTATE_ACTION(enter_estop_reset_needed)),   Stop::Keep, "RSM-05"),
  row("C08", Ev::Cycle, {St::EstopActive},        SAFESTATE_GUARD(always),                                          stay(SAFESTATE_ACTION(none)),                                                Stop::Keep, "RSM-05"),
  row("C11", Ev::Cycle, powered(),                SAFESTATE_GUARD(manual_session_panic),                            enter({St::Idle}, SAFESTATE_ACTION(enter_idle)),                             Stop::Cat0, "RSM-09, INV-ENABLE, INV-1OO2"),
  row("C12", Ev::Cycle, powered(),                SAFESTATE_GUARD(selector_differs_from_session_unless_cat1_stopping), enter({St::Stopping, St::Idle}, SAFESTATE_ACTION(enter_stopping_cat1)),             Stop::Cat1, "RSM-02, RSM-11"),
  row("C13", Ev::Cycle, powered(),                SAFESTATE_GUARD(auto_session_gate_open_unless_cat1_stopping),     enter({St::Stopping, St::Idle}, SAFESTATE_ACTION(enter_stopping_cat1)),                Stop::Cat1, "RSM-08, RSM-11, INV-GATE, INV-1OO2"),
  row("C14", Ev::Cycle, powered(),                SAFESTATE_GUARD(manual_session_enable_not_middle_unless_cat1_stopping), enter({St::Stopping, St::Idle}, SAFESTATE_ACTION(enter_stopping_cat1)),          Stop::Cat1, "RSM-09, RSM-11, INV-ENABLE, INV-1OO2"),
  row("C26", Ev::Cycle, {St::ManualJogging},      SAFESTATE_GUARD(operator_link_lost),                              enter({St::Stopping}, SAFESTATE_ACTION(enter_stopping_cat2_pause)),          Stop::Cat2, "RSM-13, seed"),
  row("C15", Ev::Cycle, {St::Arming},             SAFESTATE_GUARD(servo_ready),                                     enter({St::AutoIdle, St::ManualIdle}, SAFESTATE_ACTION(enter_operational_idle)), Stop::Keep, "RSM-07"),
  row("C16", Ev::Cycle, {St::Arming},             SAFESTATE_GUARD(arming_timer_expired),                            enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_arming_timeout)),         Stop::Cat0, "RSM-07"),
  row("C17", Ev::Cycle, {St::Arming},             SAFESTATE_GUARD(always),                                          stay(SAFESTATE_ACTION(count_state_cycle)),                                   Stop::Keep, "RSM-07"),
  row("C18", Ev::Cycle, {St::Stopping},           SAFESTATE_GUARD(stopped_cat1),                                    enter({St::Idle}, SAFESTATE_ACTION(enter_idle)),                             Stop::Keep, "RSM-11"),
  row("C28", Ev::Cycle, {St::Stopping},           SAFESTATE_GUARD(stopped_jog_stop),                                enter({St::ManualIdle}, SAFESTATE_ACTION(enter_manual_idle)),                Stop::Keep, "RSM-09, RSM-11"),
  row("C19", Ev::Cycle, {St::Stopping},           SAFESTATE_GUARD(stopped_cat2),                                    enter({St::Hold}, SAFESTATE_ACTION(enter_hold)),                             Stop::Keep, "RSM-11"),
  row("C20", Ev::Cycle, {St::Stopping},           SAFESTATE_GUARD(stop_timer_expired),                              enter({St::ErrorLockout}, SAFESTATE_ACTION(lockout_stop_timeout)),           Stop::Cat0, "RSM-11"),
  row("C21", Ev::Cycle, {St::Stopping},           SAFESTATE_GUARD(always),                                          stay(SAFESTATE_ACTION(count_state_cycle)),                                   Stop::Keep, "RSM-11"),
  row("C22", Ev::Cycle, {St::Idle},               SAFESTATE_GUARD(selector_not_t2_or_t2_confirmed),                 stay(SAFESTATE_ACTION(age_t2_confirmation)),                               Stop::Keep, "RSM-06"),
  row("C23", Ev::Cycle, any(),                    SAFESTATE_GUARD(always),                                          stay(SAFESTATE_ACTION(none)),                                                Stop::Keep, "-"),

  // ---- §6: one command popped from the queue, after §5 ----------------------------------------
  row("K01", Ev::AnyCommand, {St::ErrorLockout},  SAFESTATE_GUARD(always),                                          reject(Why::LockedOut),                                                      Stop::Keep, "RSM-04"),
  row("K02", Ev::Reset,     {St::EstopActive},    SAFESTATE_GUARD(always),                                          reject(Why::EstopPressed),                                                   Stop::Keep, "RSM-05"),
  row("K36", Ev::Reset,     any(),                SAFESTATE_GUARD(reset_submitted_before_release),                  reject(Why::EstopPressed),                                                   Stop::Keep, "RSM-05"),
  row("K03", Ev::Reset,     any_but({St::EstopResetNeeded}), SAFESTATE_GUARD(always),                               reject(Why::WrongState),                                                     Stop::Keep, "RSM-05"),
  row("K04", Ev::Reset,     any(),                SAFESTATE_GUARD(drive_fault),                                     reject(Why::DriveFault),                                                     Stop::Keep, "RSM-05"),
  row("K37", Ev::Reset,     any(),                SAFESTATE_GUARD(estop_channels_not_both_tested),                  reject(Why::ChannelTestPending),                                             Stop::Keep, "RSM-04, RSM-05"),
  row("K05", Ev::Reset,     any(),                SAFESTATE_GUARD(always),                                          enter({St::Idle}, SAFESTATE_ACTION(reset_to_idle)),                             Stop::Keep, "RSM-05, INV-RESET"),
  row("K06", Ev::ServoOn,   any_but({St::Idle}),  SAFESTATE_GUARD(always),                                          reject(Why::WrongState),                                                     Stop::Keep, "RSM-06"),
  row("K38", Ev::ServoOn,   any(),                SAFESTATE_GUARD(not_idle_at_cycle_start),                         reject(Why::WrongState),                                                     Stop::Keep, "RSM-06, RSM-03"),
  row("K07", Ev::ServoOn,   any(),                SAFESTATE_GUARD(drive_fault),                                     reject(Why::DriveFault),                                                     Stop::Keep, "RSM-06"),
  row("K08", Ev::ServoOn,   any(),                SAFESTATE_GUARD(selector_invalid),                                reject(Why::SelectorInvalid),                                                Stop::Keep, "RSM-06"),
  row("K09", Ev::ServoOn,   any(),                SAFESTATE_GUARD(selector_auto_and_gate_open),                     reject(Why::SafeguardOpen),                                                  Stop::Keep, "RSM-06"),
  row("K10", Ev::ServoOn,   any(),                SAFESTATE_GUARD(selector_manual_and_enable_not_middle),           reject(Why::EnableNotMiddle),                                                Stop::Keep, "RSM-06"),
  row("K39", Ev::ServoOn,   any(),                SAFESTATE_GUARD(selector_manual_and_enable_release_required),     reject(Why::EnableNotMiddle),                                                Stop::Keep, "RSM-06, RSM-09"),
  row("K11", Ev::ServoOn,   any(),                SAFESTATE_GUARD(selector_t2_and_not_confirmed),                   reject(Why::T2NotConfirmed),                                                 Stop::Keep, "RSM-06"),
  row("K12", Ev::ServoOn,   any(),                SAFESTATE_GUARD(always),                                          enter({St::Arming}, SAFESTATE_ACTION(enter_arming)),                         Stop::Clear, "RSM-06, RSM-07"),
  row("K13", Ev::ServoOff,  any_but({St::Arming, St::AutoIdle, St::AutoRunning, St::ManualIdle, St::ManualJogging, St::Hold}),
                                                  SAFESTATE_GUARD(always),                                          reject(Why::WrongState),                                                     Stop::Keep, "RSM-13"),
  row("K14", Ev::ServoOff,  any(),                SAFESTATE_GUARD(always),                                          enter({St::Stopping, St::Idle}, SAFESTATE_ACTION(enter_stopping_cat1)),      Stop::Cat1, "RSM-11"),
  row("K15", Ev::Start,     {St::ManualIdle, St::ManualJogging}, SAFESTATE_GUARD(always),                           reject(Why::WrongMode),                                                      Stop::Keep, "RSM-08"),
  row("K16", Ev::Start,     any_but({St::AutoIdle}), SAFESTATE_GUARD(always),                                       reject(Why::WrongState),                                                     Stop::Keep, "RSM-08"),
  row("K17", Ev::Start,     any(),                SAFESTATE_GUARD(gate_open),                                       reject(Why::SafeguardOpen),                                                  Stop::Keep, "RSM-08, INV-GATE"),
  row("K18", Ev::Start,     any(),                SAFESTATE_GUARD(always),                                          enter({St::AutoRunning}, SAFESTATE_ACTION(enter_auto_running)),              Stop::Keep, "RSM-08"),
  row("K19", Ev::Pause,     any_but({St::AutoRunning, St::ManualJogging}), SAFESTATE_GUARD(always),                 reject(Why::WrongState),                                                     Stop::Keep, "RSM-11"),
  row("K20", Ev::Pause,     any(),                SAFESTATE_GUARD(always),                                          enter({St::Stopping}, SAFESTATE_ACTION(enter_stopping_cat2_pause)),          Stop::Cat2, "RSM-11"),
  row("K21", Ev::Resume,    any_but({St::Hold}),  SAFESTATE_GUARD(always),                                          reject(Why::WrongState),                                                     Stop::Keep, "RSM-11"),
  row("K22", Ev::Resume,    any(),                SAFESTATE_GUARD(resume_to_auto_and_gate_open),                    reject(Why::SafeguardOpen),                                                  Stop::Keep, "RSM-11, INV-GATE"),
  row("K23", Ev::Resume,    any(),                SAFESTATE_GUARD(resume_to_jog_and_enable_not_middle),             reject(Why::EnableNotMiddle),                                                Stop::Keep, "RSM-11, INV-ENABLE"),
  row("K24", Ev::Resume,    any(),                SAFESTATE_GUARD(always),                                          enter({St::AutoRunning, St::ManualJogging}, SAFESTATE_ACTION(resume_motion)), Stop::Keep, "RSM-11"),
  row("K25", Ev::JogStart,  any(),                SAFESTATE_GUARD(in_auto),                                         reject(Why::JogInAuto),                                                      Stop::Keep, "RSM-08, INV-NOJOG-AUTO"),
  row("K26", Ev::JogStart,  any(),                SAFESTATE_GUARD(jog_arguments_invalid),                           reject(Why::InvalidArgument),                                                Stop::Keep, "RSM-13"),
  row("K27", Ev::JogStart,  any_but({St::ManualIdle}), SAFESTATE_GUARD(always),                                     reject(Why::WrongState),                                                     Stop::Keep, "RSM-09"),
  row("K28", Ev::JogStart,  any(),                SAFESTATE_GUARD(enable_not_middle),                               reject(Why::EnableNotMiddle),                                                Stop::Keep, "RSM-09, INV-ENABLE"),
  row("K29", Ev::JogStart,  any(),                SAFESTATE_GUARD(always),                                          enter({St::ManualJogging}, SAFESTATE_ACTION(start_jog)),                     Stop::Keep, "RSM-09, RSM-10, INV-T1SPEED"),
  row("K30", Ev::JogStop,   any(),                SAFESTATE_GUARD(in_auto),                                         reject(Why::JogInAuto),                                                      Stop::Keep, "RSM-08"),
  row("K31", Ev::JogStop,   any_but({St::ManualJogging}), SAFESTATE_GUARD(always),                                  reject(Why::WrongState),                                                     Stop::Keep, "RSM-09"),
  row("K32", Ev::JogStop,   any(),                SAFESTATE_GUARD(always),                                          enter({St::Stopping}, SAFESTATE_ACTION(enter_stopping_cat2_jog_stop)),       Stop::Cat2, "RSM-09, RSM-11"),
  row("K33", Ev::T2Confirm, any_but({St::Idle}),  SAFESTATE_GUARD(always),                                          reject(Why::WrongState),                                                     Stop::Keep, "RSM-06"),
  row("K34", Ev::T2Confirm, any(),                SAFESTATE_GUARD(selector_not_t2),                                 reject(Why::WrongMode),                                                      Stop::Keep, "RSM-06"),
  row("K35", Ev::T2Confirm, any(),                SAFESTATE_GUARD(always),                                          stay(SAFESTATE_ACTION(confirm_t2)),                                          Stop::Keep, "RSM-06"),
}};
// clang-format on

#undef SAFESTATE_GUARD
#undef SAFESTATE_ACTION

}  // namespace table_dsl

/// The table, §5 rows then §6 rows.
inline constexpr const std::array<TransitionRow, 69>& kTransitionTable = table_dsl::kRows;
inline constexpr std::size_t kCycleRowCount = 30;    // C01..C30
inline constexpr std::size_t kCommandRowCount = 39;  // K01..K39

// ---- Compile-time audit of the table ---------------------------------------------------------

namespace table_check {

[[nodiscard]] constexpr bool id_is(std::string_view id, char prefix, std::size_t number) noexcept {
  return id.size() == 3 && id[0] == prefix && id[1] == static_cast<char>('0' + number / 10) &&
         id[2] == static_cast<char>('0' + number % 10);
}

/// C rows then K rows, each id Cnn / Knn within its section's count (rows added by a later
/// change take the next free number and sit where first-match needs them: C24-C30, K36-K39).
[[nodiscard]] constexpr bool ids_in_order() noexcept {
  for (std::size_t i = 0; i < kTransitionTable.size(); ++i) {
    const bool cycle = i < kCycleRowCount;
    const std::size_t count = cycle ? kCycleRowCount : kCommandRowCount;
    bool ok = false;
    for (std::size_t n = 1; n <= count; ++n) {
      ok = ok || id_is(kTransitionTable[i].id, cycle ? 'C' : 'K', n);
    }
    if (!ok) return false;
  }
  return true;
}

[[nodiscard]] constexpr bool ids_unique() noexcept {
  for (std::size_t i = 0; i < kTransitionTable.size(); ++i) {
    for (std::size_t j = i + 1; j < kTransitionTable.size(); ++j) {
      if (kTransitionTable[i].id == kTransitionTable[j].id) return false;
    }
  }
  return true;
}

/// C rows react to the cycle, K rows to commands.
[[nodiscard]] constexpr bool events_match_sections() noexcept {
  for (std::size_t i = 0; i < kTransitionTable.size(); ++i) {
    const bool is_cycle = kTransitionTable[i].event == RowEvent::Cycle;
    if (is_cycle != (i < kCycleRowCount)) return false;
  }
  return true;
}

/// Every reject row has a reason and no action; no other row has a reason; only command
/// rows reject; Enter rows name their target(s), the others none.
[[nodiscard]] constexpr bool effects_well_formed() noexcept {
  for (const TransitionRow& r : kTransitionTable) {
    // Checked through the names, which the SAFESTATE_GUARD/ACTION macros tie to the
    // pointers: comparing function addresses is not a constant expression under every
    // compiler flag (e.g. GCC with sanitizers).
    if (r.guard_name.empty() || r.action_name.empty() || r.source.empty()) return false;
    switch (r.kind) {
      case TargetKind::Reject:
        if (r.reason == RejectReason::None || r.reason == RejectReason::QueueFull) return false;
        if (r.event == RowEvent::Cycle || r.action_name != "none") return false;
        if (!r.targets.empty() || r.stop != StopUpdate::Keep) return false;
        break;
      case TargetKind::Enter:
        if (r.reason != RejectReason::None || r.targets.empty()) return false;
        break;
      case TargetKind::Stay:
        if (r.reason != RejectReason::None || !r.targets.empty()) return false;
        break;
    }
  }
  return true;
}

/// The cycle always fires a row (C23), and every command kind always gets a result: its
/// last row is unconditional.
[[nodiscard]] constexpr bool total() noexcept {
  const TransitionRow& last = kTransitionTable[kCycleRowCount - 1];
  if (last.source != StateSet::all() || last.guard_name != "always") return false;
  constexpr std::array<RowEvent, 9> kCommandEvents{RowEvent::Reset,    RowEvent::ServoOn, RowEvent::ServoOff,
                                                   RowEvent::Start,    RowEvent::Pause,   RowEvent::Resume,
                                                   RowEvent::JogStart, RowEvent::JogStop, RowEvent::T2Confirm};
  for (const RowEvent e : kCommandEvents) {
    bool has_catch_all = false;
    for (const TransitionRow& r : kTransitionTable) {
      if (r.event == e && r.source == StateSet::all() && r.guard_name == "always") has_catch_all = true;
    }
    if (!has_catch_all) return false;
  }
  return true;
}

}  // namespace table_check

static_assert(kTransitionTable.size() == kCycleRowCount + kCommandRowCount, "69 rows: C01-C30, K01-K39");
static_assert(table_check::ids_in_order(), "row ids must be C01..C30 then K01..K39");
static_assert(table_check::ids_unique(), "row ids must be unique");
static_assert(table_check::events_match_sections(), "C rows are cycle rows, K rows command rows");
static_assert(table_check::effects_well_formed(), "every reject row needs a reason; effects must be well formed");
static_assert(table_check::total(), "the cycle and every command must always fire a row");

/// The states in which row `index` can fire at all: its source minus the states an earlier
/// unconditional row for the same event already takes (first-match). E.g. K05 (Reset
/// accepted) can fire only in ESTOP_RESET_NEEDED because K01-K03 take every other state.
/// Used by the exports and the conformance row audit.
[[nodiscard]] constexpr StateSet effective_source(std::size_t index) noexcept {
  const TransitionRow& r = kTransitionTable[index];
  std::uint16_t bits = r.source.bits();
  for (std::size_t i = 0; i < index; ++i) {
    const TransitionRow& earlier = kTransitionTable[i];
    const bool same_event =
        earlier.event == r.event || (earlier.event == RowEvent::AnyCommand && r.event != RowEvent::Cycle);
    if (same_event && earlier.guard_name == "always") {
      bits = static_cast<std::uint16_t>(bits & ~earlier.source.bits());
    }
  }
  StateSet out;
  for (const StateId s : kAllStates) {
    if ((bits & (1U << static_cast<unsigned>(s))) != 0U) out = out | StateSet{s};
  }
  return out;
}

/// Index of a row by id (for tests and exports); kTransitionTable.size() if absent.
[[nodiscard]] constexpr std::size_t row_index(std::string_view id) noexcept {
  for (std::size_t i = 0; i < kTransitionTable.size(); ++i) {
    if (kTransitionTable[i].id == id) return i;
  }
  return kTransitionTable.size();
}

}  // namespace safestate
