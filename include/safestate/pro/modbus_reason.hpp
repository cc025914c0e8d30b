// Why a frame got its action: one reason per rule of the request check, counted per reason
// by ao_modbus_server (its diagnostics counters are indexed by this enum).
#pragma once

#include <cstddef>
#include <cstdint>

namespace safestate::pro {

enum class ModbusReason : std::uint8_t {
  ok = 0,                // served
  unsupported_function,  // 01
  length_mismatch,       // 03: the MBAP length does not fit the function's PDU
  bad_quantity,          // 03: quantity 0 or above the function's maximum
  bad_byte_count,        // 03: byte count does not match the quantity
  bad_coil_value,        // 03: write single coil with a value other than 0x0000 / 0xFF00
  address_out_of_range,  // 02: the range leaves the addressed table (or the table is empty)
  wrong_unit_id,         // discarded: not addressed to this server
  wrong_protocol_id,     // discarded: MBAP protocol identifier is not 0 (not Modbus)
  reserved_function,     // discarded: function code >= 0x80 (reserved for exception responses)
  bad_mbap_length,       // connection closed: MBAP length outside 2 ... 254
  truncated_frame,       // connection closed: a frame stayed incomplete for the frame timeout
  send_failed,           // connection closed: the reply could not be sent whole (peer gone / not reading)
  write_not_allowed,     // 01: a write from a client whose address is not on the write allow-list
  write_not_armed,       // 01: a write to coil 0 without the write-enable handshake (coil 1) just before
};

inline constexpr std::size_t kModbusReasonCount = static_cast<std::size_t>(ModbusReason::write_not_armed) + 1;

}  // namespace safestate::pro
