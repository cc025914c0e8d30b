// `safestate demo protection`: the fan controller (ProtectionRuntime) closed around the
// thermal/electrical plant, one line per tick. Scenarios (docs/design/protection.md §5-§9):
// over-temperature -> protection within the 10-tick budget -> a clear request denied while
// hot -> accepted when cool; a supply dip -> protection and Degraded (the fan driver cuts
// out) -> recovery; a controlled shutdown with its stop order. Exit code 0 only if every
// scenario showed what it must (the demo checks itself, it does not just print).
#include <cstdio>
#include <cstring>
#include <string>

#include "safestate/pro/in_process_comms.hpp"
#include "safestate/pro/protection_runtime.hpp"
#include "safestate/pro/thermal_plant.hpp"

using namespace safestate::pro;  // NOLINT

namespace {

const char* name(SupervisorState s) {
  static const char* const kNames[] = {"INIT", "RUN", "DEGRADED", "SHUTTING_DOWN", "STOPPED"};
  return kNames[static_cast<int>(s)];
}
const char* name(ProtectionState s) { return s == ProtectionState::protection ? "PROTECTION" : "NORMAL"; }
const char* name(SafetyResult r) {
  static const char* const kNames[] = {"OK", "PROTECTION_ENTERED", "LATCH_BLOCKED"};
  return kNames[static_cast<int>(r)];
}
const char* name(AoId a) {
  static const char* const kNames[] = {"mon", "ctl", "saf", "dia", "com"};
  return kNames[static_cast<int>(a)];
}
const char* name(UnitId u) {
  static const char* const kNames[] = {"timer",  "dispatcher",  "monitoring", "control",
                                       "safety", "diagnostics", "comms"};
  return kNames[static_cast<int>(u)];
}

struct Demo {
  InProcessComms panel;
  ProtectionRuntime rt{panel};
  ThermalPlant plant;
  int failures = 0;
  TickReport last;

  TickReport tick(const std::string& note = "") {
    ControllerInputs in = plant.inputs();
    last = rt.tick(in);
    plant.step(last.fan_output);
    std::string d;
    for (std::size_t i = 0; i < last.dispatched.count; ++i) {
      if (!d.empty()) d += ",";
      d += name(last.dispatched.order[i]);
    }
    std::printf("t=%4u %4d C %4.1f V  fan %3u%% (actual %3.0f%%)  %-10s %-13s %s  %-18s [%s]%s%s\n", last.tick,
                in.sample.temperature_c, in.sample.voltage_dv / 10.0, last.fan_output, plant.fan_percent(),
                name(rt.safety().context().protection_state), name(last.state),
                last.row ? std::string(last.row->id).c_str() : "---", last.safety_ran ? name(last.safety_result) : "-",
                d.c_str(), note.empty() ? "" : "  <- ", note.c_str());
    return last;
  }
  void expect(bool ok, const char* what) {
    std::printf("   check: %s: %s\n", what, ok ? "yes" : "NO");
    if (!ok) ++failures;
  }
};

}  // namespace

int main() {
  Demo d;
  std::printf("Fan controller demo: tick = %u ms, protection budget 10 ticks (1 s), limits 85 C, 18.0 V, 30.0 V\n",
              kTickPeriodMs);
  std::printf(
      "columns: tick, sampled temperature, supply, fan command (and actual), protection, supervisor, row, "
      "ao_safety result, AOs dispatched in order\n\n== start-up and regulation (heat load 600 W)\n");
  d.plant.set_heat_load_w(600);
  d.tick("init: every unit started");
  d.expect(d.last.state == SupervisorState::run, "every readiness gate passed, RUN");
  for (int i = 0; i < 40; ++i) d.tick();
  d.expect(d.rt.safety().context().protection_state == ProtectionState::normal, "regulating, no protection");

  std::printf("\n== over-temperature: heat load 1800 W\n");
  d.plant.set_heat_load_w(1800);
  std::uint32_t hazard_tick = 0;
  for (int i = 0; i < 200 && d.rt.safety().context().protection_state == ProtectionState::normal; ++i) {
    const ControllerInputs in = d.plant.inputs();
    if (hazard_tick == 0 && in.sample.temperature_c > 85) hazard_tick = d.rt.data().tick + 1;
    d.tick(hazard_tick == d.rt.data().tick + 1 ? "first snapshot above 85 C" : "");
  }
  const std::uint32_t response = d.last.tick - hazard_tick + 1;
  std::printf("   protection entered in tick %u, %u tick(s) after the first hazardous snapshot (budget 10)\n",
              d.last.tick, response);
  d.expect(d.last.safety_result == SafetyResult::protection_entered && response <= 10, "protection within budget");
  d.expect(d.last.fan_output == kSafeFanCommandPercent, "fan command overridden to its safe value (100 %)");
  d.expect(d.rt.data().image.protection_state == 1, "PROTECTION published by diagnostics in the same tick");
  for (int i = 0; i < 5; ++i) d.tick();

  std::printf("\n== clear request while hot\n");
  d.panel.request_clear();
  d.tick("operator writes coil 0 (taken by comms)");
  d.tick("monitoring attaches the clear request");
  d.expect(d.last.safety_result == SafetyResult::latch_blocked, "clear denied while hot (LATCH_BLOCKED)");
  d.plant.set_heat_load_w(300);
  std::printf("\n== heat load back to 300 W; the latch holds\n");
  for (int i = 0; i < 300 && d.plant.temperature_c() > 70.0; ++i) d.tick();
  d.expect(d.rt.safety().context().protection_state == ProtectionState::protection, "still latched when cool");
  d.panel.request_clear();
  d.tick("operator writes coil 0");
  d.tick("clear request evaluated");
  d.expect(
      d.rt.safety().context().protection_state == ProtectionState::normal && d.rt.data().image.last_clear_result == 1,
      "clear accepted when cool, regulation resumes");
  for (int i = 0; i < 5; ++i) d.tick();

  std::printf("\n== supply dip to 15.0 V for 8 ticks (below 18 V; fan driver lockout at 17 V)\n");
  d.plant.set_supply_dv(150);
  bool degraded = false;
  for (int i = 0; i < 8; ++i) {
    d.tick(i == 0 ? "under-voltage; driver fault -> control FAILED" : "");
    degraded = degraded || d.last.state == SupervisorState::degraded;
  }
  d.expect(degraded, "Degraded (a required unit failed)");
  d.expect(d.rt.safety().context().protection_state == ProtectionState::protection, "under-voltage protection entered");
  d.plant.set_supply_dv(240);
  d.tick("supply back to 24.0 V");
  d.tick();
  d.expect(d.last.state == SupervisorState::run, "recovered to RUN (fault cleared, watchdog fine, units ready)");
  d.panel.request_clear();
  d.tick("operator writes coil 0");
  d.tick("clear request evaluated");
  d.expect(d.rt.safety().context().protection_state == ProtectionState::normal, "clear accepted");
  for (int i = 0; i < 3; ++i) d.tick();

  std::printf("\n== controlled shutdown\n");
  d.rt.request_shutdown();
  std::string order;
  std::uint8_t step = 0;
  for (int i = 0; i < 30 && d.last.state != SupervisorState::stopped; ++i) {
    d.tick(d.last.state == SupervisorState::run ? "shutdown requested" : "");
    if (d.last.stop_step != step) {
      step = d.last.stop_step;
      const StopStep& s = kStopOrder[step - 1];
      std::printf("   waiting for step %u: %s%s\n", step, s.outputs ? "outputs safe (control)" : "stop ",
                  s.outputs ? "" : name(s.unit));
    }
    if (!d.rt.supervisor().outputs_safe()) {
      d.expect(d.rt.status(UnitId::safety) != UnitStatus::stopped, "protection active until outputs are safe");
    }
  }
  d.expect(d.last.state == SupervisorState::stopped, "STOPPED: every unit reported stopped");
  const DiagnosticCounts& c = d.rt.diagnostics().counts();
  std::printf(
      "\ndiagnostics: %u events, %u ticks, %u Degraded, %u recoveries; fault events: sensor invalid %u, "
      "over-temperature %u, under-voltage %u, over-voltage %u, latch blocked %u\n",
      c.events, c.ticks, c.degraded, c.recoveries, c.faults[1], c.faults[2], c.faults[3], c.faults[4], c.faults[5]);
  // Diagnostics stops before safety (§9): safety's status of the tick in between is refused.
  std::printf("events not delivered (full queue, or posted to an AO already stopped): %u\n", d.rt.overflow_count());
  std::printf("\n%s: %d check(s) failed\n", d.failures == 0 ? "demo complete" : "DEMO FAILED", d.failures);
  return d.failures == 0 ? 0 : 1;
}
