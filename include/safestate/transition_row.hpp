// SPDX-License-Identifier: Apache-2.0
// One row of the transition table (design §5 and §6).
#pragma once

#include <cstdint>
#include <string_view>

#include "safestate/command_kind.hpp"
#include "safestate/reject_reason.hpp"
#include "safestate/state_set.hpp"

namespace safestate {

struct StepContext;

/// The event a row reacts to: a scan cycle (§5) or a command (§6); AnyCommand is K01.
enum class RowEvent : std::uint8_t {
  Cycle,
  AnyCommand,
  Reset,
  ServoOn,
  ServoOff,
  Start,
  Pause,
  Resume,
  JogStart,
  JogStop,
  T2Confirm,
};

[[nodiscard]] constexpr std::string_view to_string(RowEvent e) noexcept {
  switch (e) {
    case RowEvent::Cycle: return "CYCLE";
    case RowEvent::AnyCommand: return "ANY_COMMAND";
    case RowEvent::Reset: return "RESET";
    case RowEvent::ServoOn: return "SERVO_ON";
    case RowEvent::ServoOff: return "SERVO_OFF";
    case RowEvent::Start: return "START";
    case RowEvent::Pause: return "PAUSE";
    case RowEvent::Resume: return "RESUME";
    case RowEvent::JogStart: return "JOG_START";
    case RowEvent::JogStop: return "JOG_STOP";
    case RowEvent::T2Confirm: return "T2_CONFIRM";
  }
  return "?";
}

[[nodiscard]] constexpr RowEvent event_of(CommandKind k) noexcept {
  switch (k) {
    case CommandKind::Reset: return RowEvent::Reset;
    case CommandKind::ServoOn: return RowEvent::ServoOn;
    case CommandKind::ServoOff: return RowEvent::ServoOff;
    case CommandKind::Start: return RowEvent::Start;
    case CommandKind::Pause: return RowEvent::Pause;
    case CommandKind::Resume: return RowEvent::Resume;
    case CommandKind::JogStart: return RowEvent::JogStart;
    case CommandKind::JogStop: return RowEvent::JogStop;
    case CommandKind::T2Confirm: return RowEvent::T2Confirm;
  }
  return RowEvent::AnyCommand;
}

/// Enter: construct the target state afresh (even if it is the current state).
/// Stay: keep the state; the action may update its data (counters, t2_confirmed).
/// Reject: a command row with a reason; nothing changes but command_result and
/// last_reject_reason (RSM-13).
enum class TargetKind : std::uint8_t { Enter, Stay, Reject };

[[nodiscard]] constexpr std::string_view to_string(TargetKind k) noexcept {
  switch (k) {
    case TargetKind::Enter: return "ENTER";
    case TargetKind::Stay: return "STAY";
    case TargetKind::Reject: return "REJECT";
  }
  return "?";
}

/// What a row does to the status field `stop_category` (§7): Keep it, set a category, or
/// Clear it to NONE (K12 only).
enum class StopUpdate : std::uint8_t { Keep, Cat0, Cat1, Cat2, Clear };

[[nodiscard]] constexpr std::string_view to_string(StopUpdate u) noexcept {
  switch (u) {
    case StopUpdate::Keep: return "KEEP";
    case StopUpdate::Cat0: return "CAT0";
    case StopUpdate::Cat1: return "CAT1";
    case StopUpdate::Cat2: return "CAT2";
    case StopUpdate::Clear: return "NONE";
  }
  return "?";
}

using GuardFn = bool (*)(const StepContext&) noexcept;
using ActionFn = void (*)(StepContext&) noexcept;

struct TransitionRow {
  std::string_view id;  ///< "C01".."C23", "K01".."K35"
  RowEvent event;
  StateSet source;  ///< the row applies only in these states
  GuardFn guard;    ///< and only when this holds
  std::string_view guard_name;
  TargetKind kind;
  StateSet targets;     ///< possible resulting states (Enter rows); empty otherwise
  RejectReason reason;  ///< Reject rows only
  StopUpdate stop;
  ActionFn action;
  std::string_view action_name;
  std::string_view requirements;  ///< "RSM-05, INV-RESET"
};

}  // namespace safestate
