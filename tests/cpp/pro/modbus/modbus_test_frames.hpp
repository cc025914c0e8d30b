// Modbus TCP frames for the ao_modbus_server tests: an MBAP header around a PDU.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace modbus_test {

// Transaction id 0x1234, protocol id `protocol`, the MBAP length computed from the PDU.
inline std::vector<std::uint8_t> frame(std::uint8_t unit, std::initializer_list<std::uint8_t> pdu,
                                       std::uint16_t protocol = 0) {
  const auto length = static_cast<std::uint16_t>(pdu.size() + 1);
  std::vector<std::uint8_t> f(7 + pdu.size());
  f[0] = 0x12;
  f[1] = 0x34;
  f[2] = static_cast<std::uint8_t>(protocol >> 8);
  f[3] = static_cast<std::uint8_t>(protocol & 0xFF);
  f[4] = static_cast<std::uint8_t>(length >> 8);
  f[5] = static_cast<std::uint8_t>(length & 0xFF);
  f[6] = unit;
  std::size_t i = 7;
  for (const std::uint8_t b : pdu) f[i++] = b;
  return f;
}

}  // namespace modbus_test
