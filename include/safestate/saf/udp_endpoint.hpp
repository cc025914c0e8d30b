// SPDX-License-Identifier: Apache-2.0
// A non-blocking UDP socket on the IPv4 loopback interface (design §9). One datagram is
// one message; reading is bounded per cycle (kMaxInboundPerCycle) and sending never blocks.
#pragma once

#include <cstddef>
#include <cstdint>

#include "safestate/saf/codec.hpp"
#include "safestate/saf/inbound_batch.hpp"

namespace safestate::saf {

enum class UdpError : std::uint8_t { None, Socket, Bind, NonBlocking, WouldBlock, Send, Receive };

class UdpEndpoint {
 public:
  UdpEndpoint() noexcept = default;
  ~UdpEndpoint();
  UdpEndpoint(UdpEndpoint&& other) noexcept;
  UdpEndpoint& operator=(UdpEndpoint&& other) noexcept;
  UdpEndpoint(const UdpEndpoint&) = delete;
  UdpEndpoint& operator=(const UdpEndpoint&) = delete;

  /// Binds 127.0.0.1:port (0: any free port), non-blocking. On failure the endpoint stays
  /// closed and the reason (and errno in `last_errno()`) is returned.
  [[nodiscard]] UdpError open(std::uint16_t port = 0) noexcept;
  [[nodiscard]] bool is_open() const noexcept { return fd_ >= 0; }
  [[nodiscard]] std::uint16_t port() const noexcept { return port_; }
  [[nodiscard]] int last_errno() const noexcept { return errno_; }

  /// Reads datagrams until the batch is full or the socket is empty (never blocks).
  /// Returns how many were read in this call.
  std::size_t receive_batch(InboundBatch& batch) noexcept;
  /// Reads one datagram into `d` (WouldBlock when none is waiting); `from` gets the sender.
  [[nodiscard]] UdpError receive_one(Datagram& d, std::uint16_t* from = nullptr) noexcept;

  /// Sends one datagram to 127.0.0.1:port. WouldBlock (dropped, counted) if the send buffer
  /// is full.
  [[nodiscard]] UdpError send_to(std::uint16_t port, const std::uint8_t* data, std::size_t size) noexcept;
  [[nodiscard]] UdpError send_to(std::uint16_t port, const Encoded& e) noexcept {
    return send_to(port, e.bytes.data(), e.size);
  }
  [[nodiscard]] std::uint64_t send_dropped() const noexcept { return send_dropped_; }

 private:
  void close() noexcept;
  int fd_ = -1;
  std::uint16_t port_ = 0;
  int errno_ = 0;
  std::uint64_t send_dropped_ = 0;
};

}  // namespace safestate::saf
