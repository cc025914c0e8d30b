// SPDX-License-Identifier: Apache-2.0
// A non-blocking IPv4 UDP socket (design §9, §14). One datagram is one message; reading is
// bounded per cycle (kMaxInboundPerCycle), sending never blocks, every received datagram
// carries its sender, and the datagrams the kernel dropped because the receive buffer was
// full are counted (SO_RXQ_OVFL).
#pragma once

#include <cstddef>
#include <cstdint>

#include "safestate/saf/codec.hpp"
#include "safestate/saf/inbound_batch.hpp"
#include "safestate/saf/source.hpp"

namespace safestate::saf {

enum class UdpError : std::uint8_t { None, Socket, Bind, NonBlocking, WouldBlock, Send, Receive, Connect };

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
  [[nodiscard]] UdpError open(std::uint16_t port = 0) noexcept { return open(kLoopback, port); }
  /// Binds address:port (host byte order), non-blocking, with SO_RXQ_OVFL enabled.
  [[nodiscard]] UdpError open(std::uint32_t address, std::uint16_t port) noexcept;
  /// Connects the socket to `peer`: the kernel then delivers only datagrams from that
  /// address and port (sender binding below the service: a flood from any other port
  /// cannot fill this socket's receive buffer) and send() goes there.
  [[nodiscard]] UdpError connect_to(const Peer& peer) noexcept;
  [[nodiscard]] bool is_open() const noexcept { return fd_ >= 0; }
  [[nodiscard]] std::uint16_t port() const noexcept { return port_; }
  [[nodiscard]] std::uint32_t address() const noexcept { return address_; }
  [[nodiscard]] int last_errno() const noexcept { return errno_; }

  /// Reads datagrams until the batch is full or the socket is empty (never blocks), each
  /// with its sender and `role`. Returns how many were read in this call.
  std::size_t receive_batch(InboundBatch& batch, SocketRole role = SocketRole::Unknown) noexcept;
  /// Reads one datagram into `d` (WouldBlock when none is waiting); `from` gets the sender.
  [[nodiscard]] UdpError receive_one(Datagram& d, std::uint16_t* from = nullptr) noexcept;
  [[nodiscard]] UdpError receive_one(Datagram& d, Peer& from) noexcept;
  /// True when a datagram is waiting (a backlog after a full batch).
  [[nodiscard]] bool has_pending() const noexcept;
  /// Datagrams the kernel dropped because this socket's receive buffer was full, as far as
  /// the datagrams received so far tell (SO_RXQ_OVFL reports the count at each arrival).
  [[nodiscard]] std::uint64_t kernel_dropped() const noexcept { return kernel_dropped_; }

  /// Sends one datagram to 127.0.0.1:port. WouldBlock (dropped, counted) if the send buffer
  /// is full.
  [[nodiscard]] UdpError send_to(std::uint16_t port, const std::uint8_t* data, std::size_t size) noexcept {
    return send_to(Peer{kLoopback, port}, data, size);
  }
  [[nodiscard]] UdpError send_to(std::uint16_t port, const Encoded& e) noexcept {
    return send_to(port, e.bytes.data(), e.size);
  }
  [[nodiscard]] UdpError send_to(const Peer& to, const std::uint8_t* data, std::size_t size) noexcept;
  [[nodiscard]] UdpError send_to(const Peer& to, const Encoded& e) noexcept {
    return send_to(to, e.bytes.data(), e.size);
  }
  [[nodiscard]] std::uint64_t send_dropped() const noexcept { return send_dropped_; }

 private:
  void close() noexcept;
  int fd_ = -1;
  std::uint32_t address_ = kLoopback;
  std::uint16_t port_ = 0;
  int errno_ = 0;
  std::uint64_t send_dropped_ = 0;
  std::uint64_t kernel_dropped_ = 0;
  std::uint32_t last_drop_count_ = 0;  // the kernel's counter at the last arrival
};

}  // namespace safestate::saf
