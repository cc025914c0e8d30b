// SPDX-License-Identifier: Apache-2.0
// RSM-17: PLCopen single-axis state machine, and the §8 step table that the
// SystemStateManager drives it with.
#include <gtest/gtest.h>

#include <cstddef>
#include <iterator>
#include <set>
#include <string>
#include <utility>

#include "safestate/plcopen_axis.hpp"

namespace {

using safestate::AxisEvent;
using safestate::AxisReject;
using safestate::AxisState;
using safestate::kAllAxisEvents;
using safestate::kAllAxisStates;
using safestate::PlcopenAxis;
using S = AxisState;

// Compile-time checks of the pure functions.
static_assert(PlcopenAxis::step_toward(S::StandStill, S::Stopping, false) == S::Stopping);
static_assert(PlcopenAxis::step_toward(S::Disabled, S::Stopping, true) == S::Disabled);
static_assert(PlcopenAxis::is_legal_transition(S::Disabled, S::StandStill));
static_assert(!PlcopenAxis::is_legal_transition(S::Disabled, S::ContinuousMotion));
static_assert(safestate::to_string(S::SynchronizedMotion) == "SynchronizedMotion");

TEST(RSM17_PlcopenAxis, StateNamesAreTheEnumeratorNames) {
  const std::pair<AxisState, const char*> names[] = {
      {S::Disabled, "Disabled"},
      {S::StandStill, "StandStill"},
      {S::Homing, "Homing"},
      {S::DiscreteMotion, "DiscreteMotion"},
      {S::ContinuousMotion, "ContinuousMotion"},
      {S::SynchronizedMotion, "SynchronizedMotion"},
      {S::Stopping, "Stopping"},
      {S::ErrorStop, "ErrorStop"},
  };
  for (const auto& [s, n] : names) EXPECT_EQ(safestate::to_string(s), n);
}

// The rejection reasons carry their enumerator names (the diagnostics and the binding show
// them); found missing by the C++ mutation score (an emptied name survived).
TEST(RSM17_PlcopenAxis, RejectReasonNamesAreTheEnumeratorNames) {
  using R = AxisReject;
  const std::pair<AxisReject, const char*> names[] = {
      {R::None, "None"},
      {R::AxisDisabled, "AxisDisabled"},
      {R::AxisInErrorStop, "AxisInErrorStop"},
      {R::AxisStopping, "AxisStopping"},
      {R::HomingActive, "HomingActive"},
      {R::NotStandStill, "NotStandStill"},
      {R::NothingToComplete, "NothingToComplete"},
      {R::NoErrorToReset, "NoErrorToReset"},
  };
  for (const auto& [r, n] : names) EXPECT_EQ(safestate::to_string(r), n);
}

// The function blocks carry their PLCopen Part 1 names (rejections and the diagram name
// them); found missing by the C++ mutation score (an emptied name survived).
TEST(RSM17_PlcopenAxis, FunctionBlockNamesAreThePlcopenNames) {
  const std::pair<AxisEvent, const char*> names[] = {
      {AxisEvent::PowerOn, "MC_Power(on)"},
      {AxisEvent::PowerOff, "MC_Power(off)"},
      {AxisEvent::Home, "MC_Home"},
      {AxisEvent::MoveAbsolute, "MC_MoveAbsolute"},
      {AxisEvent::MoveRelative, "MC_MoveRelative"},
      {AxisEvent::Halt, "MC_Halt"},
      {AxisEvent::MoveVelocity, "MC_MoveVelocity"},
      {AxisEvent::GearIn, "MC_GearIn"},
      {AxisEvent::CamIn, "MC_CamIn"},
      {AxisEvent::Stop, "MC_Stop"},
      {AxisEvent::Done, "Done"},
      {AxisEvent::AxisError, "AxisError"},
      {AxisEvent::Reset, "MC_Reset"},
  };
  static_assert(std::size(names) == safestate::kAxisEventCount);
  for (const auto& [e, n] : names) EXPECT_EQ(safestate::to_string(e), n);
}

// The transitions of the PLCopen Part 1 single-axis diagram, written out independently of
// PlcopenAxis::transition() as an adjacency list (self-loops are "no request" and always
// legal; they are not listed).
std::set<std::pair<AxisState, AxisState>> diagram_edges() {
  std::set<std::pair<AxisState, AxisState>> e;
  for (const AxisState s : kAllAxisStates) {
    if (s != S::ErrorStop) e.insert({s, S::ErrorStop});  // axis error, from every state
    if (s != S::Disabled) e.insert({s, S::Disabled});    // MC_Power off (ErrorStop: MC_Reset unpowered)
  }
  e.insert({S::Disabled, S::StandStill});        // MC_Power on
  e.insert({S::ErrorStop, S::StandStill});       // MC_Reset, powered
  e.insert({S::StandStill, S::Homing});          // MC_Home
  e.insert({S::Homing, S::StandStill});          // homing done
  e.insert({S::DiscreteMotion, S::StandStill});  // motion done
  e.insert({S::Stopping, S::StandStill});        // MC_Stop.Done AND NOT Execute
  for (const AxisState from : {S::StandStill, S::DiscreteMotion, S::ContinuousMotion, S::SynchronizedMotion}) {
    for (const AxisState to : {S::DiscreteMotion, S::ContinuousMotion, S::SynchronizedMotion}) {
      if (from != to) e.insert({from, to});  // MC_Move*/MC_Halt, MC_MoveVelocity, MC_GearIn/CamIn
    }
  }
  for (const AxisState from :
       {S::StandStill, S::Homing, S::DiscreteMotion, S::ContinuousMotion, S::SynchronizedMotion}) {
    e.insert({from, S::Stopping});  // MC_Stop
  }
  return e;
}

TEST(RSM17_PlcopenAxis, TransitionFunctionMatchesTheDiagramEdgeForEdge) {
  const auto edges = diagram_edges();
  for (const AxisState from : kAllAxisStates) {
    for (const AxisState to : kAllAxisStates) {
      const bool expected = from == to || edges.count({from, to}) != 0;
      EXPECT_EQ(PlcopenAxis::is_legal_transition(from, to), expected)
          << safestate::to_string(from) << " -> " << safestate::to_string(to);
    }
  }
}

TEST(RSM17_PlcopenAxis, StepTowardOnlyProducesLegalTransitionsForAllInputs) {
  std::size_t checked = 0;
  for (const AxisState current : kAllAxisStates) {
    for (const AxisState desired : kAllAxisStates) {
      for (const bool speed_zero : {false, true}) {
        const AxisState next = PlcopenAxis::step_toward(current, desired, speed_zero);
        EXPECT_TRUE(PlcopenAxis::is_legal_transition(current, next))
            << safestate::to_string(current) << " toward " << safestate::to_string(desired)
            << " (speed_zero=" << speed_zero << ") gives " << safestate::to_string(next);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 8u * 8u * 2u);
}

TEST(RSM17_PlcopenAxis, StepTowardImplementsTheDesignTable) {
  const AxisState motion[] = {S::ContinuousMotion, S::SynchronizedMotion, S::DiscreteMotion, S::Homing};
  for (const bool z : {false, true}) {
    for (const AxisState c : kAllAxisStates) {
      EXPECT_EQ(PlcopenAxis::step_toward(c, S::ErrorStop, z), S::ErrorStop);  // any -> ErrorStop
      for (const AxisState d : kAllAxisStates) {
        EXPECT_EQ(PlcopenAxis::step_toward(S::ErrorStop, d, z), S::ErrorStop);  // only MC_Reset leaves
      }
      if (c != S::ErrorStop) {
        EXPECT_EQ(PlcopenAxis::step_toward(c, S::Disabled, z), S::Disabled);  // MC_Power off
      }
    }
    EXPECT_EQ(PlcopenAxis::step_toward(S::Disabled, S::Stopping, z), S::Disabled);
    for (const AxisState d :
         {S::StandStill, S::Homing, S::DiscreteMotion, S::ContinuousMotion, S::SynchronizedMotion}) {
      EXPECT_EQ(PlcopenAxis::step_toward(S::Disabled, d, z), S::StandStill);  // MC_Power on
    }
    EXPECT_EQ(PlcopenAxis::step_toward(S::Stopping, S::Stopping, z), S::Stopping);
    for (const AxisState d :
         {S::StandStill, S::Homing, S::DiscreteMotion, S::ContinuousMotion, S::SynchronizedMotion}) {
      EXPECT_EQ(PlcopenAxis::step_toward(S::Stopping, d, z), z ? S::StandStill : S::Stopping);
    }
    EXPECT_EQ(PlcopenAxis::step_toward(S::StandStill, S::StandStill, z), S::StandStill);
    EXPECT_EQ(PlcopenAxis::step_toward(S::StandStill, S::Stopping, z), S::Stopping);
    for (const AxisState c : motion) {
      EXPECT_EQ(PlcopenAxis::step_toward(c, S::Stopping, z), S::Stopping);    // MC_Stop
      EXPECT_EQ(PlcopenAxis::step_toward(c, S::StandStill, z), S::Stopping);  // MC_Stop
    }
    for (const AxisState c : {S::StandStill, S::ContinuousMotion, S::SynchronizedMotion, S::DiscreteMotion}) {
      EXPECT_EQ(PlcopenAxis::step_toward(c, S::ContinuousMotion, z), S::ContinuousMotion);
      EXPECT_EQ(PlcopenAxis::step_toward(c, S::SynchronizedMotion, z), S::SynchronizedMotion);
    }
    EXPECT_EQ(PlcopenAxis::step_toward(S::Homing, S::ContinuousMotion, z), S::Homing);
    EXPECT_EQ(PlcopenAxis::step_toward(S::Homing, S::SynchronizedMotion, z), S::Homing);
  }
}

TEST(RSM17_PlcopenAxis, StopSendsAxisThroughStoppingToStandStillThenDisabled) {
  PlcopenAxis axis;
  EXPECT_EQ(axis.state(), S::Disabled);
  axis.track(S::StandStill, true);  // ARMING done -> AUTO_IDLE
  EXPECT_EQ(axis.state(), S::StandStill);
  EXPECT_TRUE(axis.powered());
  axis.track(S::SynchronizedMotion, true);  // AUTO_RUNNING
  EXPECT_EQ(axis.state(), S::SynchronizedMotion);
  axis.track(S::Stopping, false);  // STOPPING (Cat 1), still moving
  EXPECT_EQ(axis.state(), S::Stopping);
  axis.track(S::Stopping, false);
  EXPECT_EQ(axis.state(), S::Stopping);
  axis.track(S::Disabled, true);  // STOPPING -> IDLE at zero speed: power removed
  EXPECT_EQ(axis.state(), S::Disabled);
  EXPECT_FALSE(axis.powered());
}

TEST(RSM17_PlcopenAxis, Cat2PauseHoldsAtStandStillAndResumes) {
  PlcopenAxis axis;
  axis.track(S::StandStill, true);
  axis.track(S::ContinuousMotion, true);  // MANUAL_JOGGING, jog axis
  EXPECT_EQ(axis.state(), S::ContinuousMotion);
  axis.track(S::Stopping, false);   // STOPPING CAT2
  axis.track(S::StandStill, true);  // HOLD, speed zero
  EXPECT_EQ(axis.state(), S::StandStill);
  axis.track(S::ContinuousMotion, true);  // resume
  EXPECT_EQ(axis.state(), S::ContinuousMotion);
  axis.track(S::StandStill, false);  // JOG_STOP: motion -> Stopping first
  EXPECT_EQ(axis.state(), S::Stopping);
  axis.track(S::StandStill, true);
  EXPECT_EQ(axis.state(), S::StandStill);
}

TEST(RSM17_PlcopenAxis, DriveFaultPutsAxisInErrorStopAndLockoutKeepsIt) {
  for (const AxisState start : {S::Disabled, S::StandStill, S::ContinuousMotion, S::Stopping}) {
    PlcopenAxis axis;
    axis.track(S::StandStill, true);
    if (start == S::Disabled) axis.track(S::Disabled, true);
    if (start == S::ContinuousMotion) axis.track(S::ContinuousMotion, true);
    if (start == S::Stopping) axis.track(S::Stopping, false);
    ASSERT_EQ(axis.state(), start);
    axis.track(S::ErrorStop, false);
    EXPECT_EQ(axis.state(), S::ErrorStop);
    for (const AxisState d : kAllAxisStates) {
      axis.track(d, true);
      EXPECT_EQ(axis.state(), S::ErrorStop);
    }
  }
}

TEST(RSM17_PlcopenAxis, IllegalFunctionBlocksAreRejectedWithReasonAndChangeNothing) {
  PlcopenAxis axis;
  // Disabled: no motion, no homing, no MC_Stop.
  for (const AxisEvent e : {AxisEvent::Home, AxisEvent::MoveAbsolute, AxisEvent::MoveVelocity, AxisEvent::GearIn,
                            AxisEvent::Stop, AxisEvent::Done}) {
    const auto r = axis.request(e);
    EXPECT_FALSE(r.accepted()) << safestate::to_string(e);
    EXPECT_EQ(r.reason, AxisReject::AxisDisabled);
    EXPECT_EQ(axis.state(), S::Disabled);
  }
  EXPECT_EQ(axis.mc_reset().reason, AxisReject::NoErrorToReset);

  ASSERT_TRUE(axis.mc_power(true).accepted());
  ASSERT_EQ(axis.state(), S::StandStill);
  EXPECT_EQ(axis.motion_done().reason, AxisReject::NothingToComplete);
  ASSERT_TRUE(axis.mc_home().accepted());
  ASSERT_EQ(axis.state(), S::Homing);
  // Homing is not interrupted by motion commands.
  EXPECT_EQ(axis.mc_move_velocity().reason, AxisReject::HomingActive);
  EXPECT_EQ(axis.mc_gear_in().reason, AxisReject::HomingActive);
  EXPECT_EQ(axis.mc_home().reason, AxisReject::NotStandStill);
  EXPECT_EQ(axis.state(), S::Homing);
  ASSERT_TRUE(axis.motion_done().accepted());
  ASSERT_EQ(axis.state(), S::StandStill);

  ASSERT_TRUE(axis.mc_move_velocity().accepted());
  EXPECT_EQ(axis.state(), S::ContinuousMotion);
  EXPECT_EQ(axis.mc_home().reason, AxisReject::NotStandStill);
  EXPECT_EQ(axis.motion_done().reason, AxisReject::NothingToComplete);
  ASSERT_TRUE(axis.mc_stop().accepted());
  ASSERT_EQ(axis.state(), S::Stopping);
  // Stopping: only MC_Stop (again), Done, power off and errors are taken.
  for (const AxisEvent e : {AxisEvent::Home, AxisEvent::MoveAbsolute, AxisEvent::MoveRelative, AxisEvent::Halt,
                            AxisEvent::MoveVelocity, AxisEvent::GearIn, AxisEvent::CamIn}) {
    const auto r = axis.request(e);
    EXPECT_EQ(r.reason, AxisReject::AxisStopping) << safestate::to_string(e);
    EXPECT_EQ(r.next, S::Stopping);
    EXPECT_EQ(axis.state(), S::Stopping);
  }
  EXPECT_TRUE(axis.mc_stop().accepted());
  EXPECT_EQ(axis.state(), S::Stopping);
  ASSERT_TRUE(axis.motion_done().accepted());
  EXPECT_EQ(axis.state(), S::StandStill);
}

TEST(RSM17_PlcopenAxis, MotionFunctionBlocksSelectTheirMotionState) {
  PlcopenAxis axis;
  ASSERT_TRUE(axis.mc_power(true).accepted());
  ASSERT_TRUE(axis.mc_move_absolute().accepted());
  EXPECT_EQ(axis.state(), S::DiscreteMotion);
  ASSERT_TRUE(axis.mc_move_velocity().accepted());
  EXPECT_EQ(axis.state(), S::ContinuousMotion);
  ASSERT_TRUE(axis.mc_cam_in().accepted());
  EXPECT_EQ(axis.state(), S::SynchronizedMotion);
  ASSERT_TRUE(axis.mc_move_relative().accepted());
  EXPECT_EQ(axis.state(), S::DiscreteMotion);
  ASSERT_TRUE(axis.mc_gear_in().accepted());
  EXPECT_EQ(axis.state(), S::SynchronizedMotion);
  ASSERT_TRUE(axis.mc_halt().accepted());
  EXPECT_EQ(axis.state(), S::DiscreteMotion);
  ASSERT_TRUE(axis.motion_done().accepted());
  EXPECT_EQ(axis.state(), S::StandStill);
}

TEST(RSM17_PlcopenAxis, ErrorStopIsLeftOnlyByResetToPowerDependentState) {
  PlcopenAxis axis;
  ASSERT_TRUE(axis.mc_power(true).accepted());
  ASSERT_TRUE(axis.mc_move_velocity().accepted());
  ASSERT_TRUE(axis.axis_error().accepted());
  EXPECT_EQ(axis.state(), S::ErrorStop);
  for (const AxisEvent e : {AxisEvent::Home, AxisEvent::MoveAbsolute, AxisEvent::MoveVelocity, AxisEvent::GearIn,
                            AxisEvent::Stop, AxisEvent::Done}) {
    EXPECT_EQ(axis.request(e).reason, AxisReject::AxisInErrorStop) << safestate::to_string(e);
    EXPECT_EQ(axis.state(), S::ErrorStop);
  }
  // MC_Power off with an axis error does not leave ErrorStop.
  EXPECT_TRUE(axis.mc_power(false).accepted());
  EXPECT_EQ(axis.state(), S::ErrorStop);
  // MC_Reset with power status FALSE -> Disabled.
  EXPECT_TRUE(axis.mc_reset().accepted());
  EXPECT_EQ(axis.state(), S::Disabled);

  // MC_Reset with power on -> StandStill.
  ASSERT_TRUE(axis.mc_power(true).accepted());
  ASSERT_TRUE(axis.axis_error().accepted());
  EXPECT_TRUE(axis.mc_reset().accepted());
  EXPECT_EQ(axis.state(), S::StandStill);
}

TEST(RSM17_PlcopenAxis, EveryRejectionLeavesTheStateUnchanged) {
  for (const AxisState s : kAllAxisStates) {
    for (const AxisEvent e : kAllAxisEvents) {
      for (const bool p : {false, true}) {
        const auto t = PlcopenAxis::transition(s, e, p);
        if (!t.accepted()) {
          EXPECT_EQ(t.next, s) << safestate::to_string(s) << " / " << safestate::to_string(e);
          EXPECT_NE(safestate::to_string(t.reason), "None");
        }
      }
    }
  }
}

}  // namespace
