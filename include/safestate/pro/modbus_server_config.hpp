// The settings of ao_modbus_server (docs/design/protection.md, "Modbus register map").
// The listening address is not a setting: the server binds 127.0.0.1 only.
#pragma once

#include <cstddef>
#include <cstdint>

namespace safestate::pro {

// Bounds that keep one dispatch of the server short whatever the clients do.
inline constexpr std::size_t kModbusMaxConnections = 4;
inline constexpr std::size_t kModbusMaxRequestsPerTick = 8;

struct ModbusServerConfig {
  std::uint16_t port{1502};  // 0: an ephemeral port chosen by the kernel (tests)
  std::uint8_t unit_id{1};   // also served: 0 and 0xFF (see check_modbus_request)
  // A frame still incomplete this many ticks after its first byte closes the connection.
  std::uint32_t frame_timeout_ticks{5};
  // A connection with no complete frame for this many ticks is closed (frees its slot).
  std::uint32_t idle_timeout_ticks{600};
};

}  // namespace safestate::pro
