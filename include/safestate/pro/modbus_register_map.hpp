// The Modbus register map of ao_modbus_server (docs/design/protection.md, "Modbus register
// map"): which ProcessImage field each input register and coil shows, and how it is
// encoded in 16 bits. One constexpr table; the server and the documentation follow it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "safestate/pro/process_image.hpp"

namespace safestate::pro {

// The four Modbus data tables. The fan controller populates coils and input registers;
// discrete inputs and holding registers are empty (every address is illegal there).
inline constexpr std::uint16_t kModbusCoilCount = 2;           // coil 0: latch clear, 1: write enable
inline constexpr std::uint16_t kModbusInputRegisterCount = 6;  // input registers 0..5
inline constexpr std::uint16_t kModbusDiscreteInputCount = 0;
inline constexpr std::uint16_t kModbusHoldingRegisterCount = 0;

inline constexpr std::uint16_t kLatchClearCoil = 0;
// Writing 1 arms one safety write (coil 0) of the same connection for the arm window.
inline constexpr std::uint16_t kWriteEnableCoil = 1;

// One input register: address, name (as in the design page) and unit.
struct InputRegisterSpec {
  std::uint16_t address;
  const char* name;
  const char* unit;
};

inline constexpr std::array<InputRegisterSpec, kModbusInputRegisterCount> kInputRegisters{{
    {0, "temperature", "degC, int16 two's complement"},
    {1, "supply_voltage", "0.1 V, uint16"},
    {2, "fan_command", "percent 0..100, uint16"},
    {3, "protection_state", "0 NORMAL, 1 PROTECTION"},
    {4, "supervisor_state", "0 INIT, 1 RUN, 2 DEGRADED, 3 SHUTTING_DOWN, 4 STOPPED"},
    {5, "last_clear_result", "0 none, 1 accepted, 2 denied, 3 refused"},
}};

// The 16-bit register values of `image`, indexed by address. The controller's units are the
// register's units (no rescaling); the temperature's two's complement is kept bit for bit.
[[nodiscard]] constexpr std::array<std::uint16_t, kModbusInputRegisterCount> encode_input_registers(
    const ProcessImage& image) noexcept {
  return {static_cast<std::uint16_t>(image.temperature_c),
          image.voltage_dv,
          image.fan_command_percent,
          image.protection_state,
          image.supervisor_state,
          image.last_clear_result};
}

}  // namespace safestate::pro
