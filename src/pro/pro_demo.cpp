// `safestate demo protection`: the fan controller (ProtectionRuntime) closed around the
// thermal/electrical plant, one line per tick. Scenarios (docs/design/protection.md §5-§9):
// over-temperature -> protection (outputs_disabled) within the 10-tick budget -> a clear
// request denied while hot -> accepted when cool; a supply dip -> protection and Degraded
// (the fan driver cuts out) -> recovery; a controlled shutdown with its stop order. Exit
// code 0 only if every scenario showed what it must (the demo checks itself).
//
// The communications slot is ao_modbus_server on 127.0.0.1 (an ephemeral port, printed as
// `modbus server listening on 127.0.0.1:<port>`): the clear requests come from an operator
// client in another process (`safestate demo protection` starts python -m
// safestate.pro_operator), through the write-enable handshake. While the scenario waits for
// the operator the ticks are paced (kPacedTickMs) so the client gets served.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <thread>

#include "safestate/pro/ao_modbus_server.hpp"
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

constexpr int kPacedTickMs = 2;
constexpr int kOperatorWaitTicks = 10000;  // 20 s of paced ticks: only ends a demo without a client

ModbusServerConfig server_config() {
  ModbusServerConfig c;
  c.port = 0;
  return c;
}

struct Demo {
  AoModbusServer server{server_config()};
  ProtectionRuntime rt{server};
  ThermalPlant plant;
  int failures = 0;
  TickReport last;

  TickReport tick(const std::string& note = "") {
    ControllerInputs in = plant.inputs();
    last = rt.tick(in);
    plant.step(last.fan_output, last.load_enable);
    std::string d;
    for (std::size_t i = 0; i < last.dispatched.count; ++i) {
      if (!d.empty()) d += ",";
      d += name(last.dispatched.order[i]);
    }
    std::printf("t=%4u %4d C %4.1f V  fan %3u%% (actual %3.0f%%) load %-3s %-10s %-13s %s  %-18s [%s]%s%s\n", last.tick,
                in.sample.temperature_c, in.sample.voltage_dv / 10.0, last.fan_output, plant.fan_percent(),
                last.load_enable ? "on" : "OFF", name(rt.safety().context().protection_state), name(last.state),
                last.row ? std::string(last.row->id).c_str() : "---", last.safety_ran ? name(last.safety_result) : "-",
                d.c_str(), note.empty() ? "" : "  <- ", note.c_str());
    return last;
  }
  // Paced ticks until `done` (the operator's client acted), at most kOperatorWaitTicks.
  bool wait_for_operator(const char* what, const std::function<bool()>& done) {
    std::printf("   waiting for the operator's Modbus client: %s\n", what);
    for (int i = 0; i < kOperatorWaitTicks && !done(); ++i) {
      tick();
      std::this_thread::sleep_for(std::chrono::milliseconds(kPacedTickMs));
    }
    return done();
  }
  void expect(bool ok, const char* what) {
    std::printf("   check: %s: %s\n", what, ok ? "yes" : "NO");
    if (!ok) ++failures;
  }
};

}  // namespace

int main() {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // one line at a time to the demo's reader
  Demo d;
  std::printf("Fan controller demo: tick = %u ms, protection budget 10 ticks (1 s), limits 85 C, 18.0 V, 30.0 V\n",
              kTickPeriodMs);
  std::printf(
      "columns: tick, sampled temperature, supply, fan command (and actual), equipment permissive, protection, "
      "supervisor, row, "
      "ao_safety result, AOs dispatched in order\n\n== start-up and regulation (heat load 600 W)\n");
  d.plant.set_heat_load_w(600);
  d.tick("init: every unit started");
  d.expect(d.last.state == SupervisorState::run, "every readiness gate passed, RUN");
  std::printf("modbus server listening on 127.0.0.1:%u\n", d.server.port());
  for (int i = 0; i < 40; ++i) d.tick();
  d.expect(d.rt.safety().context().protection_state == ProtectionState::normal, "regulating, no protection");

  std::printf("\n== over-temperature: the air inlet is blocked, ambient 95 C\n");
  d.plant.set_ambient_c(95);
  std::uint32_t hazard_tick = 0;
  for (int i = 0; i < 400 && d.rt.safety().context().protection_state == ProtectionState::normal; ++i) {
    const ControllerInputs in = d.plant.inputs();
    if (hazard_tick == 0 && in.sample.temperature_c > 85) hazard_tick = d.rt.data().tick + 1;
    d.tick(hazard_tick == d.rt.data().tick + 1 ? "first snapshot above 85 C" : "");
  }
  const std::uint32_t response = d.last.tick - hazard_tick + 1;
  std::printf("   protection entered in tick %u, %u tick(s) after the first hazardous snapshot (budget 10)\n",
              d.last.tick, response);
  d.expect(d.last.safety_result == SafetyResult::protection_entered && response <= 10, "protection within budget");
  d.expect(d.last.fan_output == kSafeFanCommandPercent && !d.last.load_enable,
           "outputs_disabled: equipment permissive removed, fan at its safe value (100 %)");
  d.expect(d.rt.data().image.protection_state == 1, "PROTECTION published by diagnostics in the same tick");
  for (int i = 0; i < 5; ++i) d.tick();

  std::printf("\n== clear request while hot (the equipment is off, the cabinet is at the ambient)\n");
  d.wait_for_operator("a clear while hot (coil 1, then coil 0)",
                      [&d] { return d.rt.data().last_clear == ClearOutcome::denied; });
  d.expect(d.last.safety_result == SafetyResult::latch_blocked || d.rt.data().last_clear == ClearOutcome::denied,
           "clear denied while hot (LATCH_BLOCKED)");
  d.expect(d.rt.safety().context().protection_state == ProtectionState::protection && !d.last.load_enable,
           "still latched, equipment still disabled");

  std::printf("\n== the air inlet is cleared, ambient 25 C\n");
  d.plant.set_ambient_c(25);
  d.wait_for_operator("a clear when cool",
                      [&d] { return d.rt.safety().context().protection_state == ProtectionState::normal; });
  d.expect(
      d.rt.safety().context().protection_state == ProtectionState::normal && d.rt.data().image.last_clear_result == 1,
      "clear accepted when cool, regulation resumes");
  d.tick();
  d.expect(d.last.load_enable, "equipment permissive back on");
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
  d.wait_for_operator("a clear after the recovery",
                      [&d] { return d.rt.safety().context().protection_state == ProtectionState::normal; });
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
      "over-temperature %u, under-voltage %u, over-voltage %u, latch blocked %u, hazard detected %u\n",
      c.events, c.ticks, c.degraded, c.recoveries, c.faults[1], c.faults[2], c.faults[3], c.faults[4], c.faults[5],
      c.faults[6]);
  // Diagnostics stops before safety (§9): safety's status of the tick in between is refused.
  std::printf("events not delivered (full queue, or posted to an AO already stopped): %u\n", d.rt.overflow_count());
  const ModbusServerCounters& m = d.server.counters();
  std::printf(
      "modbus: %u frame(s) served, %u write(s) refused without the write enable, %u from a client off the "
      "allow-list\n",
      m.count(ModbusReason::ok), m.count(ModbusReason::write_not_armed), m.count(ModbusReason::write_not_allowed));
  d.expect(m.count(ModbusReason::write_not_armed) >= 1, "a clear without the write-enable handshake was refused (01)");
  std::printf("\n%s: %d check(s) failed\n", d.failures == 0 ? "demo complete" : "DEMO FAILED", d.failures);
  return d.failures == 0 ? 0 : 1;
}
