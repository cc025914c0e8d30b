// GoogleTest of the whole runtime (PRO-01..05): the fan controller's units in their fixed
// order, closed around the thermal plant, through init, protection, the latch, a supply
// dip (Degraded and recovery) and the controlled shutdown.
#include <gtest/gtest.h>

#include <vector>

#include "safestate/pro/fan_speed_controller.hpp"
#include "safestate/pro/in_process_comms.hpp"
#include "safestate/pro/protection_runtime.hpp"
#include "safestate/pro/sensor_validator.hpp"
#include "safestate/pro/thermal_plant.hpp"

namespace {

using namespace safestate::pro;  // NOLINT

struct Loop {
  InProcessComms panel;
  ProtectionRuntime rt;
  ThermalPlant plant;
  explicit Loop(bool comms_fails = false, RuntimeConfig cfg = {}) : panel(comms_fails), rt(panel, cfg) {}
  TickReport tick() {
    const TickReport r = rt.tick(plant.inputs());
    plant.step(r.fan_output, r.load_enable);
    return r;
  }
  ProtectionState prot() const { return rt.safety().context().protection_state; }
};

std::vector<AoId> order(const TickReport& r) {
  return {r.dispatched.order.begin(), r.dispatched.order.begin() + static_cast<long>(r.dispatched.count)};
}

TEST(PRO05_Runtime, InitStartsEveryUnitAndRunsTheFiveAosInTheFixedOrder) {
  Loop l;
  l.plant.set_heat_load_w(500);
  const TickReport r = l.tick();
  EXPECT_EQ(r.state, SupervisorState::run);
  EXPECT_EQ(std::string(r.row->id), "I01");
  EXPECT_EQ(order(r),
            (std::vector<AoId>{AoId::monitoring, AoId::control, AoId::safety, AoId::diagnostics, AoId::comms}));
  EXPECT_EQ(l.panel.served(), 1U);
  EXPECT_EQ(l.rt.overflow_count(), 0U);
}

TEST(PRO05_Runtime, ACommsUnitThatCannotStartDegradesAndCommsIsNotDispatched) {
  Loop l(true);
  const TickReport r = l.tick();
  EXPECT_EQ(std::string(r.row->id), "I02");
  EXPECT_EQ(order(r), (std::vector<AoId>{AoId::monitoring, AoId::control, AoId::safety, AoId::diagnostics}));
  EXPECT_EQ(l.panel.served(), 0U);
}

TEST(PRO05_Runtime, InDegradedARemoteClearIsRefusedButProtectionKeepsWorking) {
  Loop l;
  l.plant.set_heat_load_w(500);
  l.tick();
  l.panel.request_clear();
  l.tick();  // comms takes the request
  // The supervisor degrades before the request is consumed: it is refused.
  ControllerInputs in = l.plant.inputs();
  in.fatal_fault = true;
  in.sample.temperature_c = 90;
  const TickReport r = l.rt.tick(in);
  EXPECT_EQ(r.state, SupervisorState::degraded);
  EXPECT_EQ(r.safety_result, SafetyResult::protection_entered);
  EXPECT_EQ(l.rt.data().last_clear, ClearOutcome::refused);
  EXPECT_EQ(r.fan_output, kSafeFanCommandPercent);
}

TEST(PRO05_Runtime, ControlledShutdownStopsInTheOrderWithProtectionUntilOutputsAreSafe) {
  Loop l;
  l.plant.set_heat_load_w(500);
  for (int i = 0; i < 5; ++i) l.tick();
  l.rt.request_shutdown();
  std::vector<UnitId> stopped;
  bool safety_before_outputs = false;
  for (int i = 0; i < 20 && l.rt.supervisor().state() != SupervisorState::stopped; ++i) {
    const TickReport r = l.tick();
    for (std::size_t u = 0; u < kUnitCount; ++u) {
      const auto id = static_cast<UnitId>(u);
      bool seen = false;
      for (UnitId s : stopped) seen = seen || s == id;
      if (!seen && l.rt.status(id) == UnitStatus::stopped) stopped.push_back(id);
    }
    if (l.rt.status(UnitId::safety) == UnitStatus::stopped && !l.rt.supervisor().outputs_safe()) {
      safety_before_outputs = true;
    }
    if (l.rt.supervisor().outputs_safe() && r.state == SupervisorState::shutting_down) {
      EXPECT_EQ(r.fan_output, kSafeFanCommandPercent);
    }
  }
  EXPECT_EQ(l.rt.supervisor().state(), SupervisorState::stopped);
  EXPECT_FALSE(safety_before_outputs);
  EXPECT_EQ(stopped, (std::vector<UnitId>{UnitId::comms, UnitId::diagnostics, UnitId::safety, UnitId::control,
                                          UnitId::monitoring, UnitId::dispatcher, UnitId::timer}));
  EXPECT_EQ(l.panel.status(), UnitStatus::stopped);
  EXPECT_EQ(l.tick().state, SupervisorState::stopped);  // nothing runs any more
}

TEST(PRO04_Response, OverTemperatureInTheClosedLoopIsProtectedWithinTheBudget) {
  Loop l;
  l.plant.set_heat_load_w(600);
  for (int i = 0; i < 30; ++i) ASSERT_EQ(l.tick().state, SupervisorState::run);
  ASSERT_EQ(l.prot(), ProtectionState::normal);
  l.plant.set_heat_load_w(1800);
  int first_hazard = -1;
  int entered = -1;
  for (int i = 0; i < 300 && entered < 0; ++i) {
    const bool hazard = l.plant.inputs().sample.temperature_c > 85;
    if (hazard && first_hazard < 0) first_hazard = i;
    const TickReport r = l.tick();
    if (r.safety_result == SafetyResult::protection_entered) {
      entered = i;
      EXPECT_EQ(r.fan_output, kSafeFanCommandPercent);
      EXPECT_EQ(l.rt.data().image.protection_state, 1U);  // published in the same tick
    }
  }
  ASSERT_GE(first_hazard, 0);
  EXPECT_EQ(entered - first_hazard + 1, 1);  // one tick, budget 10
}

TEST(PRO02_Latch, ClearDeniedWhileHotAcceptedWhenCoolThroughTheCommsSlot) {
  Loop l;
  // A blocked air inlet: hot even with the equipment disabled, so the hazard persists.
  l.plant.set_heat_load_w(600);
  l.plant.set_ambient_c(95);
  for (int i = 0; i < 300 && l.prot() == ProtectionState::normal; ++i) l.tick();
  ASSERT_EQ(l.prot(), ProtectionState::protection);
  l.panel.request_clear();
  l.tick();
  EXPECT_EQ(l.tick().safety_result, SafetyResult::latch_blocked);
  EXPECT_EQ(l.rt.data().image.last_clear_result, 2U);
  l.plant.set_ambient_c(25);
  for (int i = 0; i < 400 && l.plant.temperature_c() > 60; ++i) l.tick();
  EXPECT_EQ(l.prot(), ProtectionState::protection);  // latched while cool
  l.panel.request_clear();
  l.tick();
  l.tick();
  EXPECT_EQ(l.prot(), ProtectionState::normal);
  EXPECT_EQ(l.rt.data().image.last_clear_result, 1U);
}

TEST(PRO05_Runtime, ASupplyDipProtectsDegradesAndRecovers) {
  Loop l;
  l.plant.set_heat_load_w(500);
  for (int i = 0; i < 5; ++i) l.tick();
  l.plant.set_supply_dv(150);
  TickReport r = l.tick();
  EXPECT_EQ(r.safety_result, SafetyResult::protection_entered);
  EXPECT_EQ(l.rt.diagnostics().last_fault(), FaultCause::under_voltage);
  EXPECT_EQ(r.state, SupervisorState::degraded);  // control reported FAILED (driver lockout)
  EXPECT_EQ(order(r), (std::vector<AoId>{AoId::monitoring, AoId::safety, AoId::diagnostics}));
  l.plant.set_supply_dv(240);
  r = l.tick();
  EXPECT_EQ(std::string(r.row->id), "D01");
  EXPECT_EQ(l.rt.diagnostics().counts().recoveries, 1U);
  EXPECT_EQ(l.prot(), ProtectionState::protection);  // the latch holds through recovery
}

TEST(PRO01_Sensor, StuckOutOfRangeFlaggedAndImplausibleReadingsAreInvalid) {
  SensorValidator v;
  RawSample s{40, 240, 1, false};
  EXPECT_EQ(v.validate(s), SensorVerdict::ok);
  for (int i = 0; i < 2; ++i) EXPECT_EQ(v.validate(s), SensorVerdict::ok);  // frozen 1, 2 ticks
  EXPECT_EQ(v.validate(s), SensorVerdict::stuck);                           // frozen 3 ticks
  s.sequence = 2;
  EXPECT_EQ(v.validate(s), SensorVerdict::ok);
  s.sequence = 3;
  s.temperature_c = 70;
  EXPECT_EQ(v.validate(s), SensorVerdict::implausible_slew);
  s.sequence = 4;
  s.temperature_c = 151;
  EXPECT_EQ(v.validate(s), SensorVerdict::out_of_range);
  s.sequence = 5;
  s.temperature_c = 140;
  s.fault_flag = true;
  EXPECT_EQ(v.validate(s), SensorVerdict::flagged);
  EXPECT_FALSE(v.snapshot(s).sensor_valid);
}

TEST(PRO01_Sensor, AStuckFrontEndInTheLoopEntersProtection) {
  Loop l;
  l.plant.set_heat_load_w(500);
  for (int i = 0; i < 5; ++i) l.tick();
  l.plant.set_sensor_stuck(true);
  SafetyResult last = SafetyResult::ok;
  for (int i = 0; i < 5 && last != SafetyResult::protection_entered; ++i) last = l.tick().safety_result;
  EXPECT_EQ(last, SafetyResult::protection_entered);
  EXPECT_EQ(l.rt.diagnostics().last_fault(), FaultCause::sensor_invalid);
}

TEST(PRO03_Control, ThePiControllerRegulatesTowardsItsSetpointAndSaturates) {
  FanSpeedController pi;
  EXPECT_EQ(pi.step(30), 20);   // cold: minimum airflow
  EXPECT_EQ(pi.step(80), 100);  // hot: full
  FanSpeedController warm;
  const std::uint8_t first = warm.step(60);
  std::uint8_t later = first;
  for (int i = 0; i < 50; ++i) later = warm.step(60);
  EXPECT_GT(later, first);  // integral action: the command rises while above the setpoint
  EXPECT_LE(warm.integral_milli_percent(), 100'000);
  Loop l;
  l.plant.set_heat_load_w(600);
  for (int i = 0; i < 600; ++i) l.tick();
  EXPECT_NEAR(l.plant.temperature_c(), 55.0, 2.0);  // settles at the setpoint
  EXPECT_EQ(l.prot(), ProtectionState::normal);
}

// Issue 31 item 5: the protective state changes the outputs (outputs_disabled), the fan
// driver's fault line is the event's hazard_detected, and the fail-safe defaults of a
// dispatch cycle (docs/design/protection.md §2, §4, §4a, §13).
TEST(PRO03_OutputsDisabled, OverTemperatureRemovesThePermissiveAndTheTemperatureFalls) {
  Loop l;
  l.plant.set_heat_load_w(1800);
  TickReport r;
  for (int i = 0; i < 300 && l.prot() == ProtectionState::normal; ++i) {
    r = l.tick();
    if (l.prot() == ProtectionState::normal) {
      ASSERT_TRUE(r.load_enable);  // regulation keeps it on, fan at 100 % or not
    }
  }
  ASSERT_EQ(l.prot(), ProtectionState::protection);
  EXPECT_FALSE(r.load_enable);
  EXPECT_FALSE(l.plant.load_on());
  const double at_entry = l.plant.temperature_c();
  for (int i = 0; i < 50; ++i) EXPECT_FALSE(l.tick().load_enable);  // latched: still disabled
  EXPECT_LT(l.plant.temperature_c(), at_entry - 5.0);               // the heat source is off: it cools
}

TEST(PRO01_HazardDetected, AFanDriverFaultAloneProtectsDegradesAndStaysLatchedThroughRecovery) {
  Loop l;
  PlantParameters p;
  p.driver_lockout_dv = 200;  // the driver cuts out at 20 V: a supply of 19 V is no under-voltage hazard
  l.plant = ThermalPlant(p);
  l.plant.set_heat_load_w(500);
  for (int i = 0; i < 5; ++i) ASSERT_EQ(l.tick().state, SupervisorState::run);
  l.plant.set_supply_dv(190);
  TickReport r = l.tick();
  EXPECT_EQ(r.safety_result, SafetyResult::protection_entered);
  EXPECT_EQ(l.rt.diagnostics().last_fault(), FaultCause::hazard_detected);
  EXPECT_EQ(r.state, SupervisorState::degraded);
  EXPECT_FALSE(r.load_enable);
  EXPECT_TRUE(l.rt.safety().degraded());  // EVT_DEGRADED reached ao_safety after the dispatch cycle
  l.plant.set_supply_dv(240);
  r = l.tick();
  EXPECT_EQ(std::string(r.row->id), "D01");
  EXPECT_FALSE(l.rt.safety().degraded());            // EVT_RECOVERY
  EXPECT_EQ(l.prot(), ProtectionState::protection);  // recovery is no clear
  EXPECT_FALSE(l.tick().load_enable);
  l.panel.request_clear();
  l.tick();
  EXPECT_TRUE(l.tick().load_enable);
  EXPECT_EQ(l.prot(), ProtectionState::normal);
}

TEST(PRO05_FailSafe, ShutdownKeepsThePermissiveOffFromStepOneToTheEnd) {
  Loop l;
  l.plant.set_heat_load_w(500);
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(l.tick().load_enable);
  l.rt.request_shutdown();
  for (int i = 0; i < 20 && l.rt.supervisor().state() != SupervisorState::stopped; ++i) {
    const TickReport r = l.tick();
    if (l.rt.supervisor().outputs_safe()) {
      EXPECT_FALSE(r.load_enable);
      EXPECT_EQ(r.fan_output, kSafeFanCommandPercent);
    }
    if (r.safety_ran) {
      EXPECT_EQ(r.safety_input, SafetyInput::fresh);  // monitoring stops after safety
    }
  }
  EXPECT_EQ(l.rt.supervisor().state(), SupervisorState::stopped);
}

TEST(PRO05_FailSafe, DegradedFromTheFirstTickKeepsProtectionOnAFreshSnapshot) {
  Loop l(true);  // comms cannot start: Degraded from the first tick, comms never dispatched
  const TickReport r = l.tick();
  EXPECT_EQ(r.safety_input, SafetyInput::fresh);
  EXPECT_TRUE(r.load_enable);  // Degraded keeps the protective chain running and regulating
}

}  // namespace
