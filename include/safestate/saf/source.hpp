// SPDX-License-Identifier: Apache-2.0
// Where a datagram came from: the sender's IPv4 address and port, and which of the
// service's sockets received it (design §14, sender binding).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace safestate::saf {

/// The service's sockets: the one the Safety Client sends to, the one connected to the
/// subsystem. `Unknown` for a datagram pushed without a transport (tests, conformance).
enum class SocketRole : std::uint8_t { Unknown, Client, Subsystem };

/// An IPv4 address (host byte order) and a port.
struct Peer {
  std::uint32_t address = 0;
  std::uint16_t port = 0;
  friend constexpr bool operator==(const Peer& a, const Peer& b) noexcept {
    return a.address == b.address && a.port == b.port;
  }
  friend constexpr bool operator!=(const Peer& a, const Peer& b) noexcept { return !(a == b); }
};

inline constexpr std::uint32_t kLoopback = 0x7F00'0001;

struct Source {
  Peer peer{};
  SocketRole socket = SocketRole::Unknown;
};

/// A dotted-quad IPv4 address ("127.0.0.1"), or nothing when the text is not one.
[[nodiscard]] std::optional<std::uint32_t> parse_ipv4(std::string_view text) noexcept;

/// "a.b.c.d:port" in a fixed buffer (at most 21 characters and a terminating NUL).
struct PeerText {
  std::array<char, 24> chars{};
  [[nodiscard]] std::string_view view() const noexcept;
};
[[nodiscard]] PeerText to_text(const Peer& p) noexcept;

}  // namespace safestate::saf
