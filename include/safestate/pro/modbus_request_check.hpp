// The request check of ao_modbus_server (docs/design/protection.md, "Modbus register map"):
// every received Modbus TCP frame is classified here before libmodbus sees it, in the
// order of the protocol specification's server state diagram (MBAP header, function code
// supported, quantity/value/length, address). Only `serve` frames reach modbus_reply, so
// libmodbus never takes its error paths that sleep and flush the socket (3.1.6 does that
// for quantity errors and unknown functions, which would block the tick).
#pragma once

#include <cstddef>
#include <cstdint>

#include "safestate/pro/modbus_register_map.hpp"
#include "safestate/pro/modbus_verdict.hpp"

namespace safestate::pro {

// MBAP header: transaction id (2), protocol id (2), length (2), unit id (1).
inline constexpr std::size_t kMbapHeaderSize = 7;
// The MBAP length counts the unit id and the PDU: 1 + 1 (function) ... 1 + 253.
inline constexpr std::uint16_t kMbapMinLength = 2;
inline constexpr std::uint16_t kMbapMaxLength = 254;
inline constexpr std::size_t kModbusMaxAduSize = 6 + kMbapMaxLength;  // 260

// Unit ids served besides the configured one: 0 and 0xFF, the values the Modbus TCP
// implementation guide gives for a server addressed by its IP address alone.
inline constexpr std::uint8_t kUnitIdAny = 0xFF;
inline constexpr std::uint8_t kUnitIdZero = 0x00;

namespace modbus_fc {
inline constexpr std::uint8_t read_coils = 0x01;
inline constexpr std::uint8_t read_discrete_inputs = 0x02;
inline constexpr std::uint8_t read_holding_registers = 0x03;
inline constexpr std::uint8_t read_input_registers = 0x04;
inline constexpr std::uint8_t write_single_coil = 0x05;
inline constexpr std::uint8_t write_single_register = 0x06;
inline constexpr std::uint8_t write_multiple_coils = 0x0F;
inline constexpr std::uint8_t write_multiple_registers = 0x10;
}  // namespace modbus_fc

// Quantity limits of the specification (v1.1b3 §6.1-6.12).
inline constexpr std::uint16_t kMaxReadBits = 2000;
inline constexpr std::uint16_t kMaxReadRegisters = 125;
inline constexpr std::uint16_t kMaxWriteBits = 1968;
inline constexpr std::uint16_t kMaxWriteRegisters = 123;
inline constexpr std::uint16_t kCoilOn = 0xFF00;
inline constexpr std::uint16_t kCoilOff = 0x0000;

[[nodiscard]] constexpr std::uint16_t be16(const std::uint8_t* p) noexcept {
  return static_cast<std::uint16_t>((p[0] << 8) | p[1]);
}

// The MBAP length field of a complete header: a frame's total size is 6 + length. A length
// outside kMbapMinLength ... kMbapMaxLength means the stream cannot be framed.
[[nodiscard]] constexpr bool mbap_length_valid(std::uint16_t length) noexcept {
  return length >= kMbapMinLength && length <= kMbapMaxLength;
}

namespace modbus_check_detail {

[[nodiscard]] constexpr ModbusVerdict exception(ModbusException code, ModbusReason reason) noexcept {
  return {ModbusAction::reply_exception, code, reason, false};
}

// The size of the table a data-access function addresses.
[[nodiscard]] constexpr std::uint16_t table_size(std::uint8_t fc) noexcept {
  switch (fc) {
    case modbus_fc::read_coils:
    case modbus_fc::write_single_coil:
    case modbus_fc::write_multiple_coils: return kModbusCoilCount;
    case modbus_fc::read_discrete_inputs: return kModbusDiscreteInputCount;
    case modbus_fc::read_input_registers: return kModbusInputRegisterCount;
    default:  // holding registers: read, write single, write multiple
      return kModbusHoldingRegisterCount;
  }
}

// Quantity (and byte count) rule of a function whose PDU length already matched.
[[nodiscard]] constexpr ModbusReason quantity_reason(std::uint8_t fc, const std::uint8_t* pdu) noexcept {
  const std::uint16_t word = be16(pdu + 3);  // quantity, or the value of a single write
  switch (fc) {
    case modbus_fc::read_coils:
    case modbus_fc::read_discrete_inputs:
      return (word < 1 || word > kMaxReadBits) ? ModbusReason::bad_quantity : ModbusReason::ok;
    case modbus_fc::read_holding_registers:
    case modbus_fc::read_input_registers:
      return (word < 1 || word > kMaxReadRegisters) ? ModbusReason::bad_quantity : ModbusReason::ok;
    case modbus_fc::write_single_coil:
      return (word == kCoilOn || word == kCoilOff) ? ModbusReason::ok : ModbusReason::bad_coil_value;
    case modbus_fc::write_single_register: return ModbusReason::ok;
    case modbus_fc::write_multiple_coils:
      if (word < 1 || word > kMaxWriteBits) return ModbusReason::bad_quantity;
      return pdu[5] == (word + 7) / 8 ? ModbusReason::ok : ModbusReason::bad_byte_count;
    default:  // write multiple registers
      if (word < 1 || word > kMaxWriteRegisters) return ModbusReason::bad_quantity;
      return pdu[5] == 2 * word ? ModbusReason::ok : ModbusReason::bad_byte_count;
  }
}

}  // namespace modbus_check_detail

// Classifies one complete frame `adu[0 .. size)` (size = 6 + a valid MBAP length) received
// by the server whose configured unit id is `unit_id`.
[[nodiscard]] constexpr ModbusVerdict check_modbus_request(const std::uint8_t* adu, std::size_t size,
                                                           std::uint8_t unit_id) noexcept {
  using namespace modbus_check_detail;
  if (be16(adu + 2) != 0) return {ModbusAction::discard, ModbusException::none, ModbusReason::wrong_protocol_id, false};
  const std::uint8_t unit = adu[6];
  if (unit != unit_id && unit != kUnitIdAny && unit != kUnitIdZero) {
    return {ModbusAction::discard, ModbusException::none, ModbusReason::wrong_unit_id, false};
  }
  const std::uint8_t* pdu = adu + kMbapHeaderSize;
  const std::size_t pdu_size = size - kMbapHeaderSize;
  const std::uint8_t fc = pdu[0];
  // 0x80 ... 0xFF mark exception responses: no exception reply (fc + 0x80) can be formed for
  // them (0x84 would be answered as 0x04, a normal read response), so they are dropped.
  if (fc >= 0x80) return {ModbusAction::discard, ModbusException::none, ModbusReason::reserved_function, false};
  std::size_t expected_pdu = 0;
  switch (fc) {
    case modbus_fc::read_coils:
    case modbus_fc::read_discrete_inputs:
    case modbus_fc::read_holding_registers:
    case modbus_fc::read_input_registers:
    case modbus_fc::write_single_coil:
    case modbus_fc::write_single_register:
      expected_pdu = 5;  // function, address, quantity or value
      break;
    case modbus_fc::write_multiple_coils:
    case modbus_fc::write_multiple_registers:
      expected_pdu = pdu_size >= 6 ? 6 + std::size_t{pdu[5]} : 6;  // ... byte count, values
      break;
    default: return exception(ModbusException::illegal_function, ModbusReason::unsupported_function);
  }
  if (pdu_size != expected_pdu) return exception(ModbusException::illegal_data_value, ModbusReason::length_mismatch);
  const ModbusReason quantity = quantity_reason(fc, pdu);
  if (quantity != ModbusReason::ok) return exception(ModbusException::illegal_data_value, quantity);

  const std::uint16_t address = be16(pdu + 1);
  const bool single = fc == modbus_fc::write_single_coil || fc == modbus_fc::write_single_register;
  const std::uint32_t count = single ? 1U : be16(pdu + 3);
  if (std::uint32_t{address} + count > table_size(fc)) {
    return exception(ModbusException::illegal_data_address, ModbusReason::address_out_of_range);
  }
  // Coil 0 := 1 (coil 1, the write enable, requests nothing by itself).
  const bool clear = address == kLatchClearCoil && ((fc == modbus_fc::write_single_coil && be16(pdu + 3) == kCoilOn) ||
                                                    (fc == modbus_fc::write_multiple_coils && (pdu[6] & 0x01U) != 0));
  return {ModbusAction::serve, ModbusException::none, ModbusReason::ok, clear};
}

}  // namespace safestate::pro
