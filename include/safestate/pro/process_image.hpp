// The process image the communications unit serves (PRO-05, docs/design/protection.md §9,
// "Modbus register map"): what the controller shows an operator after each tick. The
// runtime fills it at the end of the tick's dispatch cycle (after diagnostics, so it is
// this tick's status) and hands it to CommunicationsUnit::on_tick; the unit only reads it.
// A plain struct of fixed-width fields: each field is one Modbus item, in the controller's
// own units (the server copies the values, it does not rescale them).
#pragma once

#include <cstdint>

namespace safestate::pro {

struct ProcessImage {
  // Input register 0: validated temperature in whole degrees Celsius, signed (two's
  // complement in the 16-bit register); the sensor range is -40 ... 150.
  std::int16_t temperature_c{0};
  // Input register 1: supply voltage in decivolts (0.1 V), 0 ... 600.
  std::uint16_t voltage_dv{0};
  // Input register 2: the fan command written to the driver this tick, in percent
  // 0 ... 100, after the protection override (100 while protection is active).
  std::uint16_t fan_command_percent{0};
  // Input register 3: sm_protection's state: 0 NORMAL, 1 PROTECTION.
  std::uint16_t protection_state{0};
  // Input register 4: the runtime supervisor's state: 0 INIT, 1 RUN, 2 DEGRADED,
  // 3 SHUTTING_DOWN, 4 STOPPED.
  std::uint16_t supervisor_state{0};
  // Input register 5: the outcome of the last latch clear request the controller consumed:
  // 0 none consumed yet, 1 accepted (protection left or nothing to clear), 2 denied
  // (LATCH_BLOCKED: a hazard persisted), 3 refused (not dispatched: supervisor not in RUN).
  std::uint16_t last_clear_result{0};
  // Coil 0 (read-back): 1 while a latch clear request is pending in the controller, i.e.
  // taken from the server but not yet consumed by a tick; 0 otherwise. A client writes 1
  // to request a clear; the server ORs the requests it has not yet handed over.
  std::uint8_t latch_clear_request{0};
};

}  // namespace safestate::pro
