// SPDX-License-Identifier: Apache-2.0
// A minimal blocking WebSocket client over POSIX sockets, for the operator link's tests and
// bench (RFC 6455: the opening handshake, masked text frames out, unmasked frames in). It
// depends on nothing but libc, so the tests compile fast and talk to the bridge the way
// any browser does.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace link_test {

class WsClient {
 public:
  WsClient() = default;
  WsClient(const WsClient&) = delete;
  WsClient& operator=(const WsClient&) = delete;
  ~WsClient() { close(); }

  /// Connects to 127.0.0.1:`port` and completes the opening handshake.
  bool connect(std::uint16_t port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd_ < 0) return false;
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) return false;
    int one = 1;
    ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    const std::string req =
        "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
        "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n";
    if (!write_all(req.data(), req.size())) return false;
    std::string head;
    char c = 0;
    while (head.find("\r\n\r\n") == std::string::npos) {
      if (::recv(fd_, &c, 1, 0) != 1) return false;
      head += c;
    }
    return head.rfind("HTTP/1.1 101", 0) == 0;
  }

  /// One masked text frame.
  bool send_text(const std::string& text) {
    std::string f;
    f += static_cast<char>(0x81);
    const std::size_t n = text.size();
    if (n < 126) {
      f += static_cast<char>(0x80 | n);
    } else if (n < 65536) {
      f += static_cast<char>(0x80 | 126);
      f += static_cast<char>(n >> 8);
      f += static_cast<char>(n & 0xFF);
    } else {
      f += static_cast<char>(0x80 | 127);
      for (int i = 7; i >= 0; --i) f += static_cast<char>((static_cast<std::uint64_t>(n) >> (8 * i)) & 0xFF);
    }
    const unsigned char mask[4] = {0x12, 0x34, 0x56, 0x78};
    f.append(reinterpret_cast<const char*>(mask), 4);
    for (std::size_t i = 0; i < n; ++i) f += static_cast<char>(text[i] ^ static_cast<char>(mask[i % 4]));
    return write_all(f.data(), f.size());
  }

  /// Reads what arrives within `timeout_ms`; appends complete text messages to `out`.
  /// FALSE once the connection is closed.
  bool pump(int timeout_ms, std::vector<std::string>* out = nullptr) {
    if (fd_ < 0) return false;
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) <= 0) return true;
    char buf[65536];
    const ssize_t r = ::recv(fd_, buf, sizeof buf, MSG_DONTWAIT);
    if (r <= 0) {
      close();
      return false;
    }
    in_.append(buf, static_cast<std::size_t>(r));
    parse(out);
    return fd_ >= 0;
  }

  /// Reads until a message containing `needle` arrives (or `timeout_ms` of silence).
  bool wait_for(const std::string& needle, int timeout_ms, std::string* message = nullptr) {
    for (int quiet = 0; quiet < timeout_ms; quiet += 10) {
      std::vector<std::string> got;
      if (!pump(10, &got)) return false;
      for (const std::string& m : got) {
        if (m.find(needle) != std::string::npos) {
          if (message != nullptr) *message = m;
          return true;
        }
      }
      if (!got.empty()) quiet = 0;
    }
    return false;
  }

  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  [[nodiscard]] bool open() const { return fd_ >= 0; }
  [[nodiscard]] std::uint64_t messages() const { return messages_; }

 private:
  bool write_all(const char* p, std::size_t n) {
    while (n > 0) {
      const ssize_t w = ::send(fd_, p, n, MSG_NOSIGNAL);
      if (w <= 0) return false;
      p += w;
      n -= static_cast<std::size_t>(w);
    }
    return true;
  }

  void parse(std::vector<std::string>* out) {
    for (;;) {
      if (in_.size() < 2) return;
      const auto b1 = static_cast<unsigned char>(in_[1]);
      std::size_t len = b1 & 0x7F;
      std::size_t at = 2;
      if (len == 126) {
        if (in_.size() < 4) return;
        len = static_cast<std::size_t>(static_cast<unsigned char>(in_[2])) << 8 | static_cast<unsigned char>(in_[3]);
        at = 4;
      } else if (len == 127) {
        if (in_.size() < 10) return;
        len = 0;
        for (int i = 2; i < 10; ++i) len = len << 8 | static_cast<unsigned char>(in_[static_cast<std::size_t>(i)]);
        at = 10;
      }
      if (in_.size() < at + len) return;
      const int opcode = static_cast<unsigned char>(in_[0]) & 0x0F;
      if (opcode == 0x8) {  // close
        close();
        return;
      }
      if (opcode == 0x1) {
        ++messages_;
        if (out != nullptr) out->push_back(in_.substr(at, len));
      }
      in_.erase(0, at + len);
    }
  }

  int fd_{-1};
  std::string in_;
  std::uint64_t messages_{0};
};

}  // namespace link_test
