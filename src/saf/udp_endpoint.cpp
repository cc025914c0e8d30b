// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/udp_endpoint.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace safestate::saf {
namespace {

sockaddr_in socket_address(const Peer& p) noexcept {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(p.port);
  a.sin_addr.s_addr = htonl(p.address);
  return a;
}

}  // namespace

UdpEndpoint::~UdpEndpoint() { close(); }

UdpEndpoint::UdpEndpoint(UdpEndpoint&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      address_(other.address_),
      port_(other.port_),
      errno_(other.errno_),
      send_dropped_(other.send_dropped_),
      kernel_dropped_(other.kernel_dropped_),
      last_drop_count_(other.last_drop_count_) {}

UdpEndpoint& UdpEndpoint::operator=(UdpEndpoint&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = std::exchange(other.fd_, -1);
    address_ = other.address_;
    port_ = other.port_;
    errno_ = other.errno_;
    send_dropped_ = other.send_dropped_;
    kernel_dropped_ = other.kernel_dropped_;
    last_drop_count_ = other.last_drop_count_;
  }
  return *this;
}

void UdpEndpoint::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

UdpError UdpEndpoint::open(std::uint32_t address, std::uint16_t port) noexcept {
  close();
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (fd < 0) {
    errno_ = errno;
    return UdpError::Socket;
  }
  const sockaddr_in addr = socket_address(Peer{address, port});
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
    errno_ = errno;
    ::close(fd);
    return UdpError::Bind;
  }
  const int flags = ::fcntl(fd, F_GETFL, 0);
  if (flags < 0 || ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) != 0) {
    errno_ = errno;
    ::close(fd);
    return UdpError::NonBlocking;
  }
  // The kernel's drop counter on every received datagram (Linux); without it drops go
  // uncounted, which only weakens the diagnostics, not the E-stop timeout.
  const int on = 1;
  (void)::setsockopt(fd, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof on);
  sockaddr_in bound{};
  socklen_t len = sizeof bound;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &len);
  fd_ = fd;
  address_ = address;
  port_ = ntohs(bound.sin_port);
  kernel_dropped_ = 0;
  last_drop_count_ = 0;
  return UdpError::None;
}

UdpError UdpEndpoint::connect_to(const Peer& peer) noexcept {
  const sockaddr_in dst = socket_address(peer);
  if (::connect(fd_, reinterpret_cast<const sockaddr*>(&dst), sizeof dst) != 0) {
    errno_ = errno;
    return UdpError::Connect;
  }
  return UdpError::None;
}

UdpError UdpEndpoint::receive_one(Datagram& d, Peer& from) noexcept {
  sockaddr_in src{};
  iovec iov{d.bytes.data(), d.bytes.size()};
  alignas(cmsghdr) std::array<char, CMSG_SPACE(sizeof(std::uint32_t))> control{};
  msghdr msg{};
  msg.msg_name = &src;
  msg.msg_namelen = sizeof src;
  msg.msg_iov = &iov;
  msg.msg_iovlen = 1;
  msg.msg_control = control.data();
  msg.msg_controllen = control.size();
  // MSG_TRUNC: the real length of a longer datagram, so that it is rejected as OVERSIZED.
  const ssize_t n = ::recvmsg(fd_, &msg, MSG_TRUNC);
  if (n < 0) {
    errno_ = errno;
    return (errno == EAGAIN || errno == EWOULDBLOCK) ? UdpError::WouldBlock : UdpError::Receive;
  }
  for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c != nullptr; c = CMSG_NXTHDR(&msg, c)) {
    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_RXQ_OVFL) {
      std::uint32_t count = 0;
      std::memcpy(&count, CMSG_DATA(c), sizeof count);
      // The counter is cumulative (and wraps at 2^32): the difference is what was dropped
      // since the previous arrival.
      kernel_dropped_ += static_cast<std::uint32_t>(count - last_drop_count_);
      last_drop_count_ = count;
    }
  }
  d.size = static_cast<std::size_t>(n);
  from = Peer{ntohl(src.sin_addr.s_addr), ntohs(src.sin_port)};
  return UdpError::None;
}

UdpError UdpEndpoint::receive_one(Datagram& d, std::uint16_t* from) noexcept {
  Peer peer{};
  const UdpError e = receive_one(d, peer);
  if (e == UdpError::None && from != nullptr) *from = peer.port;
  return e;
}

bool UdpEndpoint::has_pending() const noexcept {
  std::uint8_t byte = 0;
  return ::recv(fd_, &byte, 1, MSG_PEEK | MSG_DONTWAIT) >= 0;
}

std::size_t UdpEndpoint::receive_batch(InboundBatch& batch, SocketRole role) noexcept {
  std::size_t read = 0;
  while (batch.count < batch.items.size()) {
    Peer from{};
    if (receive_one(batch.items[batch.count], from) != UdpError::None) break;
    batch.sources[batch.count] = Source{from, role};
    ++batch.count;
    ++read;
  }
  return read;
}

UdpError UdpEndpoint::send_to(const Peer& to, const std::uint8_t* data, std::size_t size) noexcept {
  const sockaddr_in dst = socket_address(to);
  const ssize_t n = ::sendto(fd_, data, size, MSG_DONTWAIT, reinterpret_cast<const sockaddr*>(&dst), sizeof dst);
  if (n < 0) {
    errno_ = errno;
    ++send_dropped_;
    return (errno == EAGAIN || errno == EWOULDBLOCK) ? UdpError::WouldBlock : UdpError::Send;
  }
  return UdpError::None;
}

}  // namespace safestate::saf
