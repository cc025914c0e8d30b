// The write authorisation of ao_modbus_server (docs/design/protection.md, "Modbus register
// map", "Writes that change safety state"): which safety coils a served frame writes, and
// whether the client may write it now. Pure and constexpr: the server applies it to every
// frame the request check would serve, before libmodbus sees it.
#pragma once

#include <cstdint>

#include "safestate/pro/modbus_reason.hpp"
#include "safestate/pro/modbus_register_map.hpp"
#include "safestate/pro/modbus_request_check.hpp"

namespace safestate::pro {

// What a frame the request check accepted writes.
struct ModbusWrite {
  bool is_write{false};    // functions 0x05, 0x06, 0x0F, 0x10
  bool latch_coil{false};  // the frame writes coil 0 (any value)
  bool arm{false};         // the frame writes coil 1 := 1 (and not coil 0)
  bool disarm{false};      // the frame writes coil 1 := 0 (and not coil 0)
};

// `adu` is a complete frame check_modbus_request classified as `serve`.
[[nodiscard]] constexpr ModbusWrite classify_write(const std::uint8_t* adu) noexcept {
  const std::uint8_t* pdu = adu + kMbapHeaderSize;
  const std::uint8_t fc = pdu[0];
  ModbusWrite w;
  w.is_write = fc == modbus_fc::write_single_coil || fc == modbus_fc::write_single_register ||
               fc == modbus_fc::write_multiple_coils || fc == modbus_fc::write_multiple_registers;
  if (fc != modbus_fc::write_single_coil && fc != modbus_fc::write_multiple_coils) return w;
  const std::uint16_t address = be16(pdu + 1);
  const std::uint32_t count = fc == modbus_fc::write_single_coil ? 1U : be16(pdu + 3);
  w.latch_coil = address <= kLatchClearCoil && kLatchClearCoil < address + count;
  const bool covers_enable = address <= kWriteEnableCoil && kWriteEnableCoil < address + count;
  if (!covers_enable || w.latch_coil) return w;  // a frame that writes coil 0 never arms
  const bool on = fc == modbus_fc::write_single_coil ? be16(pdu + 3) == kCoilOn
                                                     : ((pdu[6] >> (kWriteEnableCoil - address)) & 0x01U) != 0;
  w.arm = on;
  w.disarm = !on;
  return w;
}

// The refusal of a write (ModbusReason::ok: allowed), given whether the client's address
// is on the allow-list and whether its connection holds an unexpired arm.
[[nodiscard]] constexpr ModbusReason authorize_write(const ModbusWrite& w, bool client_allowed, bool armed) noexcept {
  if (!w.is_write) return ModbusReason::ok;
  if (!client_allowed) return ModbusReason::write_not_allowed;
  if (w.latch_coil && !armed) return ModbusReason::write_not_armed;
  return ModbusReason::ok;
}

}  // namespace safestate::pro
