// What ao_modbus_server has done since start(): frames per reason, connections. Read by
// diagnostics and the tests; updated without allocation.
#pragma once

#include <array>
#include <cstdint>

#include "safestate/pro/modbus_reason.hpp"

namespace safestate::pro {

struct ModbusServerCounters {
  std::array<std::uint32_t, kModbusReasonCount> frames{};  // indexed by ModbusReason
  std::uint32_t connections_accepted{0};
  std::uint32_t connections_refused{0};  // all kModbusMaxConnections slots were in use
  std::uint32_t connections_closed{0};   // by the peer, an error, a timeout or stop()
  std::uint32_t idle_timeouts{0};

  [[nodiscard]] std::uint32_t count(ModbusReason reason) const noexcept {
    return frames[static_cast<std::size_t>(reason)];
  }
};

}  // namespace safestate::pro
