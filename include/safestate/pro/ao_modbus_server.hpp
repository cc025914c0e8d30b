// ao_modbus_server: the communications unit of the fan controller (PRO-05, rank 5 of the
// dispatch order, non-critical; docs/design/protection.md, "Modbus register map"). Serves
// Modbus TCP on 127.0.0.1 through libmodbus: input registers 0-5 from the ProcessImage, coil
// 0 as the latch clear request, coil 1 as its write enable. Writes are served only to
// allow-listed client addresses, and a write to coil 0 only within the arm window of a
// write enable on the same connection (modbus_write_guard.hpp); refusals are answered with
// exception 01 and counted.
//
// Never blocks the tick: every socket is non-blocking, on_tick() polls with timeout 0,
// accepts at most kModbusMaxConnections clients, and handles at most
// kModbusMaxRequestsPerTick frames per call. Frames are assembled in a fixed buffer per
// connection; only frames the request check accepts are handed to modbus_reply.
// Heap: start() allocates libmodbus's context and mapping (init); nothing after that.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "safestate/pro/communications_unit.hpp"
#include "safestate/pro/modbus_request_check.hpp"
#include "safestate/pro/modbus_server_config.hpp"
#include "safestate/pro/modbus_server_counters.hpp"

struct _modbus;
struct _modbus_mapping_t;

namespace safestate::pro {

class AoModbusServer final : public CommunicationsUnit {
 public:
  explicit AoModbusServer(ModbusServerConfig config = {}) noexcept : config_(config) {}
  ~AoModbusServer() override;

  [[nodiscard]] UnitStatus start() noexcept override;
  void on_tick(const ProcessImage& image) noexcept override;
  [[nodiscard]] CommsRequests take_requests() noexcept override;
  [[nodiscard]] UnitStatus stop() noexcept override;
  [[nodiscard]] UnitStatus status() const noexcept override { return status_; }

  // The bound TCP port (the kernel's choice when config.port is 0); 0 before start().
  [[nodiscard]] std::uint16_t port() const noexcept { return port_; }
  [[nodiscard]] std::size_t open_connections() const noexcept;
  [[nodiscard]] const ModbusServerCounters& counters() const noexcept { return counters_; }

 private:
  struct Connection {
    int fd{-1};
    std::array<std::uint8_t, kModbusMaxAduSize> buffer{};
    std::size_t used{0};
    std::uint32_t frame_start_tick{0};  // tick of the first byte of the buffered frame
    std::uint32_t last_frame_tick{0};   // tick of the last complete frame (or the accept)
    bool write_allowed{false};          // the peer's address is on the write allow-list
    bool armed{false};                  // coil 1 written 1: one write to coil 0 allowed ...
    std::uint32_t armed_tick{0};        // ... until arm_window_ticks after this tick
  };
  [[nodiscard]] bool armed(const Connection& c) const noexcept {
    return c.armed && tick_ - c.armed_tick < config_.arm_window_ticks;
  }
  [[nodiscard]] bool allowed(std::uint32_t host_address) const noexcept;

  void accept_clients() noexcept;
  void receive(Connection& c) noexcept;
  // Handles the oldest complete frame of `c`; false if it has none (or was closed).
  bool handle_frame(Connection& c, const ProcessImage& image) noexcept;
  void expire(Connection& c) noexcept;
  void close_connection(Connection& c) noexcept;
  void count(ModbusReason reason) noexcept { ++counters_.frames[static_cast<std::size_t>(reason)]; }

  ModbusServerConfig config_;
  UnitStatus status_{UnitStatus::init};
  _modbus* ctx_{nullptr};
  _modbus_mapping_t* mapping_{nullptr};
  int listen_fd_{-1};
  std::uint16_t port_{0};
  std::uint32_t tick_{0};
  std::size_t next_first_{0};  // round-robin start, so no client starves the others
  bool clear_requested_{false};
  std::array<Connection, kModbusMaxConnections> connections_{};
  ModbusServerCounters counters_{};
};

}  // namespace safestate::pro
