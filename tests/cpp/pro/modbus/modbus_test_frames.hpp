// Modbus TCP frames for the ao_modbus_server tests: an MBAP header around a PDU.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <vector>

namespace modbus_test {

// Transaction id 0x1234, protocol id `protocol`, the MBAP length computed from the PDU.
inline std::vector<std::uint8_t> frame(std::uint8_t unit, std::initializer_list<std::uint8_t> pdu,
                                       std::uint16_t protocol = 0) {
  const auto length = static_cast<std::uint16_t>(pdu.size() + 1);
  std::vector<std::uint8_t> f{0x12, 0x34, static_cast<std::uint8_t>(protocol >> 8), static_cast<std::uint8_t>(protocol & 0xFF),
                              static_cast<std::uint8_t>(length >> 8), static_cast<std::uint8_t>(length & 0xFF), unit};
  f.insert(f.end(), pdu);
  return f;
}

}  // namespace modbus_test
