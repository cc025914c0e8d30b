// SPDX-License-Identifier: Apache-2.0
// PLCopen Motion Control single-axis state machine (RSM-17).
//
// States and transitions follow the PLCopen "Function blocks for motion control" Part 1
// (v2.0) single-axis state diagram:
//
//   Disabled      --MC_Power(Enable, Status)-->                         StandStill
//   any but ErrorStop --MC_Power(Enable = FALSE), no axis error-->      Disabled
//   any           --axis error-->                                       ErrorStop
//   ErrorStop     --MC_Reset, power status FALSE-->                     Disabled
//   ErrorStop     --MC_Reset, power status TRUE-->                      StandStill
//   StandStill    --MC_Home-->                                          Homing
//   Homing        --Done-->                                             StandStill
//   StandStill, DiscreteMotion, ContinuousMotion, SynchronizedMotion
//                 --MC_MoveAbsolute/MC_MoveRelative/MC_Halt-->          DiscreteMotion
//                 --MC_MoveVelocity-->                                  ContinuousMotion
//                 --MC_GearIn/MC_CamIn-->                               SynchronizedMotion
//   DiscreteMotion --Done-->                                            StandStill
//   StandStill, Homing, DiscreteMotion, ContinuousMotion, SynchronizedMotion, Stopping
//                 --MC_Stop-->                                          Stopping
//   Stopping      --MC_Stop.Done AND NOT MC_Stop.Execute-->             StandStill
//
// A function block issued in a state where the diagram does not allow it is rejected: the
// state is unchanged and the result carries a reason code (AxisReject). Everything is
// constexpr/noexcept and allocation-free (RSM-15).
//
// For the SystemStateManager, step_toward() implements the step table of
// docs/design/system-state-manager.md §8: one legal transition per cycle toward the axis
// state the manager's state wants.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate {

enum class AxisState : std::uint8_t {
  Disabled,
  StandStill,
  Homing,
  DiscreteMotion,
  ContinuousMotion,
  SynchronizedMotion,
  Stopping,
  ErrorStop,
};

inline constexpr std::size_t kAxisStateCount = 8;

inline constexpr std::array<AxisState, kAxisStateCount> kAllAxisStates{
    AxisState::Disabled,         AxisState::StandStill,         AxisState::Homing,   AxisState::DiscreteMotion,
    AxisState::ContinuousMotion, AxisState::SynchronizedMotion, AxisState::Stopping, AxisState::ErrorStop,
};

[[nodiscard]] constexpr std::string_view to_string(AxisState s) noexcept {
  switch (s) {
    case AxisState::Disabled: return "Disabled";
    case AxisState::StandStill: return "StandStill";
    case AxisState::Homing: return "Homing";
    case AxisState::DiscreteMotion: return "DiscreteMotion";
    case AxisState::ContinuousMotion: return "ContinuousMotion";
    case AxisState::SynchronizedMotion: return "SynchronizedMotion";
    case AxisState::Stopping: return "Stopping";
    case AxisState::ErrorStop: return "ErrorStop";
  }
  return "?";
}

/// Requests to the axis: PLCopen function blocks and the drive events of the diagram.
enum class AxisEvent : std::uint8_t {
  PowerOn,       ///< MC_Power Enable = TRUE (and the drive reports Status = TRUE)
  PowerOff,      ///< MC_Power Enable = FALSE
  Home,          ///< MC_Home
  MoveAbsolute,  ///< MC_MoveAbsolute
  MoveRelative,  ///< MC_MoveRelative
  Halt,          ///< MC_Halt (a discrete motion to zero velocity)
  MoveVelocity,  ///< MC_MoveVelocity
  GearIn,        ///< MC_GearIn
  CamIn,         ///< MC_CamIn
  Stop,          ///< MC_Stop (Execute rising edge)
  Done,          ///< Homing / discrete motion done, or MC_Stop.Done AND NOT MC_Stop.Execute
  AxisError,     ///< the drive reports an axis error
  Reset,         ///< MC_Reset
};

inline constexpr std::size_t kAxisEventCount = 13;

inline constexpr std::array<AxisEvent, kAxisEventCount> kAllAxisEvents{
    AxisEvent::PowerOn, AxisEvent::PowerOff,     AxisEvent::Home,   AxisEvent::MoveAbsolute, AxisEvent::MoveRelative,
    AxisEvent::Halt,    AxisEvent::MoveVelocity, AxisEvent::GearIn, AxisEvent::CamIn,        AxisEvent::Stop,
    AxisEvent::Done,    AxisEvent::AxisError,    AxisEvent::Reset,
};

[[nodiscard]] constexpr std::string_view to_string(AxisEvent e) noexcept {
  switch (e) {
    case AxisEvent::PowerOn: return "MC_Power(on)";
    case AxisEvent::PowerOff: return "MC_Power(off)";
    case AxisEvent::Home: return "MC_Home";
    case AxisEvent::MoveAbsolute: return "MC_MoveAbsolute";
    case AxisEvent::MoveRelative: return "MC_MoveRelative";
    case AxisEvent::Halt: return "MC_Halt";
    case AxisEvent::MoveVelocity: return "MC_MoveVelocity";
    case AxisEvent::GearIn: return "MC_GearIn";
    case AxisEvent::CamIn: return "MC_CamIn";
    case AxisEvent::Stop: return "MC_Stop";
    case AxisEvent::Done: return "Done";
    case AxisEvent::AxisError: return "AxisError";
    case AxisEvent::Reset: return "MC_Reset";
  }
  return "?";
}

/// Why a request was rejected (None = accepted).
enum class AxisReject : std::uint8_t {
  None,
  AxisDisabled,       ///< motion / MC_Home / MC_Stop / Done while Disabled
  AxisInErrorStop,    ///< anything but MC_Reset, MC_Power and errors while in ErrorStop
  AxisStopping,       ///< motion / MC_Home while Stopping (MC_Stop not yet released)
  HomingActive,       ///< motion / MC_Home while Homing
  NotStandStill,      ///< MC_Home outside StandStill
  NothingToComplete,  ///< Done in a state without a finishing motion
  NoErrorToReset,     ///< MC_Reset outside ErrorStop
};

[[nodiscard]] constexpr std::string_view to_string(AxisReject r) noexcept {
  switch (r) {
    case AxisReject::None: return "None";
    case AxisReject::AxisDisabled: return "AxisDisabled";
    case AxisReject::AxisInErrorStop: return "AxisInErrorStop";
    case AxisReject::AxisStopping: return "AxisStopping";
    case AxisReject::HomingActive: return "HomingActive";
    case AxisReject::NotStandStill: return "NotStandStill";
    case AxisReject::NothingToComplete: return "NothingToComplete";
    case AxisReject::NoErrorToReset: return "NoErrorToReset";
  }
  return "?";
}

/// Outcome of one request: the reason (None when accepted) and the resulting state.
struct [[nodiscard]] AxisTransition {
  AxisReject reason;
  AxisState next;  ///< the state after the request (the unchanged state when rejected)

  [[nodiscard]] constexpr bool accepted() const noexcept { return reason == AxisReject::None; }
};

class PlcopenAxis {
 public:
  constexpr PlcopenAxis() noexcept = default;

  [[nodiscard]] constexpr AxisState state() const noexcept { return state_; }
  /// MC_Power.Status: the drive's power stage is enabled.
  [[nodiscard]] constexpr bool powered() const noexcept { return powered_; }

  // ---- The PLCopen diagram as a pure function -------------------------------------------

  /// The transition `event` causes in `current`; `powered` is MC_Power.Status (it matters
  /// only for MC_Reset in ErrorStop). Rejected requests return the unchanged state.
  [[nodiscard]] static constexpr AxisTransition transition(AxisState current, AxisEvent event, bool powered) noexcept {
    using S = AxisState;
    using E = AxisEvent;
    using R = AxisReject;
    const auto ok = [](S next) constexpr { return AxisTransition{R::None, next}; };
    const auto no = [current](R why) constexpr { return AxisTransition{why, current}; };

    // Events legal in every state.
    if (event == E::AxisError) return ok(S::ErrorStop);
    if (event == E::PowerOff) {
      // MC_Power off leads to Disabled only when the axis has no error (ErrorStop stays).
      return ok(current == S::ErrorStop ? S::ErrorStop : S::Disabled);
    }
    if (event == E::PowerOn) {
      // Disabled -> StandStill; in every other state MC_Power(on) is already in effect.
      return ok(current == S::Disabled ? S::StandStill : current);
    }
    if (event == E::Reset) {
      if (current != S::ErrorStop) return no(R::NoErrorToReset);
      return ok(powered ? S::StandStill : S::Disabled);
    }

    switch (current) {
      case S::ErrorStop: return no(R::AxisInErrorStop);
      case S::Disabled: return no(R::AxisDisabled);
      case S::Stopping:
        if (event == E::Stop) return ok(S::Stopping);
        if (event == E::Done) return ok(S::StandStill);
        return no(R::AxisStopping);
      case S::Homing:
        if (event == E::Stop) return ok(S::Stopping);
        if (event == E::Done) return ok(S::StandStill);
        if (event == E::Home) return no(R::NotStandStill);
        return no(R::HomingActive);
      case S::StandStill:
      case S::DiscreteMotion:
      case S::ContinuousMotion:
      case S::SynchronizedMotion:
        switch (event) {
          case E::Home: return current == S::StandStill ? ok(S::Homing) : no(R::NotStandStill);
          case E::MoveAbsolute:
          case E::MoveRelative:
          case E::Halt: return ok(S::DiscreteMotion);
          case E::MoveVelocity: return ok(S::ContinuousMotion);
          case E::GearIn:
          case E::CamIn: return ok(S::SynchronizedMotion);
          case E::Stop: return ok(S::Stopping);
          case E::Done: return current == S::DiscreteMotion ? ok(S::StandStill) : no(R::NothingToComplete);
          default: break;
        }
        break;
    }
    return no(R::NothingToComplete);  // unreachable: every (state, event) is handled above
  }

  /// True when `from -> to` is a transition of the PLCopen diagram (staying is always
  /// legal: no request issued). Enumerates every event under both power statuses.
  [[nodiscard]] static constexpr bool is_legal_transition(AxisState from, AxisState to) noexcept {
    if (from == to) return true;
    for (const AxisEvent e : kAllAxisEvents) {
      for (const bool p : {false, true}) {
        const AxisTransition t = transition(from, e, p);
        if (t.accepted() && t.next == to) return true;
      }
    }
    return false;
  }

  // ---- Requests on this axis (state unchanged when rejected) ------------------------------

  [[nodiscard]] AxisTransition request(AxisEvent event) noexcept;

  [[nodiscard]] AxisTransition mc_power(bool enable) noexcept {
    return request(enable ? AxisEvent::PowerOn : AxisEvent::PowerOff);
  }
  [[nodiscard]] AxisTransition mc_home() noexcept { return request(AxisEvent::Home); }
  [[nodiscard]] AxisTransition mc_move_absolute() noexcept { return request(AxisEvent::MoveAbsolute); }
  [[nodiscard]] AxisTransition mc_move_relative() noexcept { return request(AxisEvent::MoveRelative); }
  [[nodiscard]] AxisTransition mc_halt() noexcept { return request(AxisEvent::Halt); }
  [[nodiscard]] AxisTransition mc_move_velocity() noexcept { return request(AxisEvent::MoveVelocity); }
  [[nodiscard]] AxisTransition mc_gear_in() noexcept { return request(AxisEvent::GearIn); }
  [[nodiscard]] AxisTransition mc_cam_in() noexcept { return request(AxisEvent::CamIn); }
  [[nodiscard]] AxisTransition mc_stop() noexcept { return request(AxisEvent::Stop); }
  [[nodiscard]] AxisTransition motion_done() noexcept { return request(AxisEvent::Done); }
  [[nodiscard]] AxisTransition axis_error() noexcept { return request(AxisEvent::AxisError); }
  [[nodiscard]] AxisTransition mc_reset() noexcept { return request(AxisEvent::Reset); }

  // ---- Driven by the SystemStateManager (design §8) --------------------------------------

  /// One step of the §8 table from `current` toward `desired`; `speed_zero` = the cycle's
  /// speed level is ZERO. The manager never desires Homing or DiscreteMotion; for those
  /// (inputs outside the table) an axis that is enabled and not stopping stays where it is.
  // clang-format off
  [[nodiscard]] static constexpr AxisState step_toward(AxisState current, AxisState desired,
                                                       bool speed_zero) noexcept {
    using S = AxisState;
    if (desired == S::ErrorStop) return S::ErrorStop;            // any -> ErrorStop
    if (current == S::ErrorStop) return S::ErrorStop;            // only MC_Reset leaves it
    if (desired == S::Disabled) return S::Disabled;              // MC_Power off
    if (current == S::Disabled) {
      return desired == S::Stopping ? S::Disabled                // MC_Stop not accepted
                                    : S::StandStill;             // MC_Power on
    }
    if (current == S::Stopping) {
      if (desired == S::Stopping) return S::Stopping;
      return speed_zero ? S::StandStill : S::Stopping;           // MC_Stop done
    }
    if (desired == S::Stopping) return S::Stopping;              // MC_Stop
    if (current == S::StandStill) {
      if (desired == S::ContinuousMotion || desired == S::SynchronizedMotion) return desired;
      return S::StandStill;                                      // StandStill (or outside table)
    }
    // current is Homing, DiscreteMotion, ContinuousMotion or SynchronizedMotion.
    if (desired == S::StandStill) return S::Stopping;            // MC_Stop
    if (desired == S::ContinuousMotion || desired == S::SynchronizedMotion) {
      return current == S::Homing ? S::Homing : desired;         // homing is not interrupted
    }
    return current;                                              // Homing / DiscreteMotion desired
  }
  // clang-format on

  /// Applies step_toward() to this axis (keeps MC_Power.Status in step).
  void track(AxisState desired, bool speed_zero) noexcept;

  /// Back to power-on state (Disabled, unpowered): re-initialisation of the controller.
  constexpr void reinitialise() noexcept {
    state_ = AxisState::Disabled;
    powered_ = false;
  }

 private:
  AxisState state_{AxisState::Disabled};
  bool powered_{false};
};

}  // namespace safestate
