#include "safestate/pro/ao_modbus_server.hpp"

#include "safestate/pro/modbus_write_guard.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>

namespace safestate::pro {

namespace {

constexpr const char* kLoopbackAddress = "127.0.0.1";

bool set_non_blocking(int fd) noexcept {
  const int flags = fcntl(fd, F_GETFL, 0);
  return flags >= 0 && fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0;
}

}  // namespace

AoModbusServer::~AoModbusServer() {
  (void)stop();
  if (ctx_ != nullptr) {
    modbus_set_socket(ctx_, -1);
    modbus_free(ctx_);
  }
  if (mapping_ != nullptr) modbus_mapping_free(mapping_);
}

UnitStatus AoModbusServer::start() noexcept {
  if (status_ != UnitStatus::init) return status_;
  status_ = UnitStatus::failed;
  ctx_ = modbus_new_tcp(kLoopbackAddress, config_.port);
  mapping_ = modbus_mapping_new_start_address(0, kModbusCoilCount, 0, kModbusDiscreteInputCount, 0,
                                              kModbusHoldingRegisterCount, 0, kModbusInputRegisterCount);
  if (ctx_ == nullptr || mapping_ == nullptr) return status_;
  // Defence in depth: libmodbus sleeps for the response timeout before some exception
  // replies; the request check keeps those frames from modbus_reply, and 1 us bounds it.
  if (modbus_set_response_timeout(ctx_, 0, 1) != 0) return status_;
  listen_fd_ = modbus_tcp_listen(ctx_, static_cast<int>(kModbusMaxConnections));
  if (listen_fd_ < 0) return status_;
  sockaddr_in bound{};
  socklen_t len = sizeof bound;
  if (!set_non_blocking(listen_fd_) || getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&bound), &len) != 0) {
    close(listen_fd_);
    listen_fd_ = -1;
    return status_;
  }
  port_ = ntohs(bound.sin_port);
  status_ = UnitStatus::ready;
  return status_;
}

std::size_t AoModbusServer::open_connections() const noexcept {
  std::size_t n = 0;
  for (const Connection& c : connections_) n += c.fd >= 0 ? 1U : 0U;
  return n;
}

void AoModbusServer::close_connection(Connection& c) noexcept {
  if (c.fd < 0) return;
  close(c.fd);
  c.fd = -1;
  c.used = 0;
  ++counters_.connections_closed;
}

bool AoModbusServer::allowed(std::uint32_t host_address) const noexcept {
  for (std::size_t i = 0; i < config_.write_allowlist_size && i < config_.write_allowlist.size(); ++i) {
    if (config_.write_allowlist[i] == host_address) return true;
  }
  return false;
}

void AoModbusServer::accept_clients() noexcept {
  // At most one accept per slot and tick, plus one to refuse: bounded work.
  for (std::size_t attempt = 0; attempt <= kModbusMaxConnections; ++attempt) {
    sockaddr_in peer{};
    socklen_t peer_len = sizeof peer;
    const int fd = accept4(listen_fd_, reinterpret_cast<sockaddr*>(&peer), &peer_len, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return;  // EAGAIN: nobody waiting (other errors: retried next tick)
    Connection* slot = nullptr;
    for (Connection& c : connections_) {
      if (c.fd < 0) {
        slot = &c;
        break;
      }
    }
    if (slot == nullptr) {
      close(fd);
      ++counters_.connections_refused;
      continue;
    }
    const int one = 1;
    (void)setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    slot->fd = fd;
    slot->used = 0;
    slot->last_frame_tick = tick_;
    slot->write_allowed = peer.sin_family == AF_INET && allowed(ntohl(peer.sin_addr.s_addr));
    slot->armed = false;
    ++counters_.connections_accepted;
  }
}

void AoModbusServer::receive(Connection& c) noexcept {
  const std::size_t room = c.buffer.size() - c.used;
  if (room == 0) return;  // a whole frame is buffered and waits for the request budget
  const ssize_t n = recv(c.fd, c.buffer.data() + c.used, room, MSG_DONTWAIT);
  if (n > 0) {
    if (c.used == 0) c.frame_start_tick = tick_;
    c.used += static_cast<std::size_t>(n);
  } else if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
    close_connection(c);  // the peer closed, or the socket failed
  }
}

bool AoModbusServer::handle_frame(Connection& c, const ProcessImage& image) noexcept {
  if (c.fd < 0 || c.used < kMbapHeaderSize) return false;
  const std::uint16_t length = be16(c.buffer.data() + 4);
  if (!mbap_length_valid(length)) {
    count(ModbusReason::bad_mbap_length);
    close_connection(c);
    return false;
  }
  const std::size_t size = 6U + length;
  if (c.used < size) return false;

  ModbusVerdict verdict = check_modbus_request(c.buffer.data(), size, config_.unit_id);
  ModbusWrite write{};
  if (verdict.action == ModbusAction::serve) {
    write = classify_write(c.buffer.data());
    const ModbusReason refusal = authorize_write(write, c.write_allowed, armed(c));
    if (refusal != ModbusReason::ok)
      verdict = {ModbusAction::reply_exception, ModbusException::illegal_function, refusal, false};
  }
  modbus_set_socket(ctx_, c.fd);
  int sent = 0;
  switch (verdict.action) {
    case ModbusAction::serve:
      // Coil 0 reads back 1 while a clear request is pending (here or in the controller).
      mapping_->tab_bits[kLatchClearCoil] = (clear_requested_ || image.latch_clear_request != 0) ? 1 : 0;
      mapping_->tab_bits[kWriteEnableCoil] = armed(c) ? 1 : 0;  // reads back this connection's arm
      sent = modbus_reply(ctx_, c.buffer.data(), static_cast<int>(size), mapping_);
      if (sent > 0) {
        if (verdict.requests_latch_clear) clear_requested_ = true;
        if (write.latch_coil) c.armed = false;  // one write per handshake
        if (write.arm) {
          c.armed = true;
          c.armed_tick = tick_;
        }
        if (write.disarm) c.armed = false;
      }
      break;
    case ModbusAction::reply_exception:
      sent = modbus_reply_exception(ctx_, c.buffer.data(), static_cast<unsigned>(verdict.exception));
      break;
    case ModbusAction::discard:
    case ModbusAction::close_connection: break;
  }
  count(verdict.reason);
  if (sent < 0 || verdict.action == ModbusAction::close_connection) {
    if (sent < 0) count(ModbusReason::send_failed);
    close_connection(c);
    return false;
  }
  std::memmove(c.buffer.data(), c.buffer.data() + size, c.used - size);
  c.used -= size;
  c.last_frame_tick = tick_;
  c.frame_start_tick = tick_;  // the next buffered frame's bytes arrived by now
  return true;
}

void AoModbusServer::expire(Connection& c) noexcept {
  if (c.fd < 0) return;
  // Only an incomplete frame times out; complete ones wait for the request budget.
  const bool incomplete = c.used > 0 && (c.used < kMbapHeaderSize || c.used < 6U + be16(c.buffer.data() + 4));
  if (incomplete && tick_ - c.frame_start_tick >= config_.frame_timeout_ticks) {
    count(ModbusReason::truncated_frame);
    close_connection(c);
  } else if (c.used == 0 && tick_ - c.last_frame_tick >= config_.idle_timeout_ticks) {
    ++counters_.idle_timeouts;
    close_connection(c);
  }
}

void AoModbusServer::on_tick(const ProcessImage& image) noexcept {
  if (status_ != UnitStatus::ready) return;
  ++tick_;
  const auto registers = encode_input_registers(image);
  std::memcpy(mapping_->tab_input_registers, registers.data(), sizeof registers);

  accept_clients();
  std::array<pollfd, kModbusMaxConnections> fds{};
  for (std::size_t i = 0; i < connections_.size(); ++i) fds[i] = {connections_[i].fd, POLLIN, 0};
  if (poll(fds.data(), fds.size(), 0) > 0) {  // fd -1 entries are ignored by poll
    for (std::size_t i = 0; i < connections_.size(); ++i) {
      if ((fds[i].revents & (POLLIN | POLLHUP | POLLERR)) != 0) receive(connections_[i]);
    }
  }

  // One frame per connection per round, starting at a rotating connection.
  std::size_t handled = 0;
  bool progress = true;
  while (progress && handled < kModbusMaxRequestsPerTick) {
    progress = false;
    for (std::size_t k = 0; k < connections_.size() && handled < kModbusMaxRequestsPerTick; ++k) {
      if (handle_frame(connections_[(next_first_ + k) % connections_.size()], image)) {
        ++handled;
        progress = true;
      }
    }
  }
  next_first_ = (next_first_ + 1) % connections_.size();
  for (Connection& c : connections_) expire(c);
}

CommsRequests AoModbusServer::take_requests() noexcept {
  CommsRequests requests;
  requests.latch_clear_request = clear_requested_;
  clear_requested_ = false;
  return requests;
}

UnitStatus AoModbusServer::stop() noexcept {
  for (Connection& c : connections_) close_connection(c);
  if (listen_fd_ >= 0) {
    close(listen_fd_);
    listen_fd_ = -1;
  }
  clear_requested_ = false;  // nobody consumes it any more
  status_ = UnitStatus::stopped;
  return status_;
}

}  // namespace safestate::pro
