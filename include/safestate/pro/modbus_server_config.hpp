// The settings of ao_modbus_server (docs/design/protection.md, "Modbus register map").
// The listening address is not a setting: the server binds 127.0.0.1 only.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace safestate::pro {

// Bounds that keep one dispatch of the server short whatever the clients do.
inline constexpr std::size_t kModbusMaxConnections = 4;
inline constexpr std::size_t kModbusMaxRequestsPerTick = 8;
inline constexpr std::size_t kModbusMaxWriteClients = 4;
inline constexpr std::uint32_t kLoopbackHost = 0x7F000001;  // 127.0.0.1, host byte order

struct ModbusServerConfig {
  std::uint16_t port{1502};  // 0: an ephemeral port chosen by the kernel (tests)
  std::uint8_t unit_id{1};   // also served: 0 and 0xFF (see check_modbus_request)
  // A frame still incomplete this many ticks after its first byte closes the connection.
  std::uint32_t frame_timeout_ticks{5};
  // A connection with no complete frame for this many ticks is closed (frees its slot).
  std::uint32_t idle_timeout_ticks{600};
  // Writes (functions 0x05, 0x06, 0x0F, 0x10) are served only to clients whose IPv4 source
  // address (host byte order) is one of the first write_allowlist_size entries; reads are
  // open to every client. The loopback interface is 127.0.0.0/8, so a local client can
  // come from another address than 127.0.0.1.
  std::array<std::uint32_t, kModbusMaxWriteClients> write_allowlist{kLoopbackHost};
  std::size_t write_allowlist_size{1};
  // Writing coil 1 := 1 arms one write to coil 0 on the same connection for this many
  // ticks (20 = 2 s); the write consumes it.
  std::uint32_t arm_window_ticks{20};
};

}  // namespace safestate::pro
