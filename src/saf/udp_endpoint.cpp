// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/udp_endpoint.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <utility>

namespace safestate::saf {
namespace {

sockaddr_in loopback(std::uint16_t port) noexcept {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  return a;
}

}  // namespace

UdpEndpoint::~UdpEndpoint() { close(); }

UdpEndpoint::UdpEndpoint(UdpEndpoint&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), port_(other.port_), errno_(other.errno_), send_dropped_(other.send_dropped_) {}

UdpEndpoint& UdpEndpoint::operator=(UdpEndpoint&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = std::exchange(other.fd_, -1);
    port_ = other.port_;
    errno_ = other.errno_;
    send_dropped_ = other.send_dropped_;
  }
  return *this;
}

void UdpEndpoint::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

UdpError UdpEndpoint::open(std::uint16_t port) noexcept {
  close();
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (fd < 0) {
    errno_ = errno;
    return UdpError::Socket;
  }
  const sockaddr_in addr = loopback(port);
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
  sockaddr_in bound{};
  socklen_t len = sizeof bound;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &len);
  fd_ = fd;
  port_ = ntohs(bound.sin_port);
  return UdpError::None;
}

UdpError UdpEndpoint::receive_one(Datagram& d, std::uint16_t* from) noexcept {
  sockaddr_in src{};
  socklen_t len = sizeof src;
  // MSG_TRUNC: the real length of a longer datagram, so that it is rejected as OVERSIZED.
  const ssize_t n = ::recvfrom(fd_, d.bytes.data(), d.bytes.size(), MSG_TRUNC, reinterpret_cast<sockaddr*>(&src), &len);
  if (n < 0) {
    errno_ = errno;
    return (errno == EAGAIN || errno == EWOULDBLOCK) ? UdpError::WouldBlock : UdpError::Receive;
  }
  d.size = static_cast<std::size_t>(n);
  if (from != nullptr) *from = ntohs(src.sin_port);
  return UdpError::None;
}

std::size_t UdpEndpoint::receive_batch(InboundBatch& batch) noexcept {
  std::size_t read = 0;
  while (batch.count < batch.items.size()) {
    if (receive_one(batch.items[batch.count]) != UdpError::None) break;
    ++batch.count;
    ++read;
  }
  return read;
}

UdpError UdpEndpoint::send_to(std::uint16_t port, const std::uint8_t* data, std::size_t size) noexcept {
  const sockaddr_in dst = loopback(port);
  const ssize_t n = ::sendto(fd_, data, size, MSG_DONTWAIT, reinterpret_cast<const sockaddr*>(&dst), sizeof dst);
  if (n < 0) {
    errno_ = errno;
    ++send_dropped_;
    return (errno == EAGAIN || errno == EWOULDBLOCK) ? UdpError::WouldBlock : UdpError::Send;
  }
  return UdpError::None;
}

}  // namespace safestate::saf
