// PRO-05 communications unit: ao_modbus_server in process over a loopback socket — the
// registers served, the coil write handed over once, truncated frames and a full connection
// table handled within the tick, no heap after start(), stop() disconnecting everyone.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "../../counting_allocator.hpp"
#include "modbus_test_frames.hpp"
#include "safestate/pro/ao_modbus_server.hpp"

namespace {

using namespace safestate::pro;
using modbus_test::frame;
using Bytes = std::vector<std::uint8_t>;

int connect_to(std::uint16_t port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  const int one = 1;  // no Nagle: a frame the server discards gets no reply to carry the ACK
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(port);
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

void send_all(int fd, const Bytes& b) { ASSERT_EQ(send(fd, b.data(), b.size(), 0), static_cast<ssize_t>(b.size())); }

// `n` copies of `f`, back to back: pipelined requests.
Bytes repeated(const Bytes& f, std::size_t n) {
  Bytes out;
  for (std::size_t i = 0; i < n; ++i) out.insert(out.end(), f.begin(), f.end());
  return out;
}

// Ticks the server until `fd` has a reply (at most `ticks` ticks); the reply or empty.
Bytes tick_until_reply(AoModbusServer& server, const ProcessImage& image, int fd, int ticks = 200) {
  for (int i = 0; i < ticks; ++i) {
    server.on_tick(image);
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 1) > 0) {
      std::uint8_t buf[300];
      const ssize_t n = recv(fd, buf, sizeof buf, 0);
      return n > 0 ? Bytes(buf, buf + n) : Bytes{};
    }
  }
  return {};
}

// The reply to `read input registers 0..5` (transaction 0x1234) for the fixture's image.
const Bytes kImageReply{0x12, 0x34, 0, 0, 0, 15, 1, 0x04, 12, 0xFF, 0xF9, 0, 245, 0, 55, 0, 0, 0, 1, 0, 0};

class PRO05_ModbusServer : public ::testing::Test {
 protected:
  void SetUp() override {
    config_.port = 0;
    config_.frame_timeout_ticks = 3;
    server_ = std::make_unique<AoModbusServer>(config_);
    ASSERT_EQ(server_->start(), UnitStatus::ready);
    image_.temperature_c = -7;
    image_.voltage_dv = 245;
    image_.fan_command_percent = 55;
    image_.supervisor_state = 1;
  }
  ModbusServerConfig config_;
  std::unique_ptr<AoModbusServer> server_;
  ProcessImage image_;
};

TEST_F(PRO05_ModbusServer, ReadInputRegistersReturnsTheProcessImage) {
  const int fd = connect_to(server_->port());
  ASSERT_GE(fd, 0);
  send_all(fd, frame(1, {0x04, 0, 0, 0, 6}));
  const Bytes reply = tick_until_reply(*server_, image_, fd);
  EXPECT_EQ(reply, kImageReply);
  close(fd);
}

TEST_F(PRO05_ModbusServer, ACoilWriteIsHandedOverExactlyOnce) {
  const int fd = connect_to(server_->port());
  send_all(fd, frame(1, {0x05, 0, 1, 0xFF, 0x00}));  // the write enable first
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x05, 0, 1, 0xFF, 0x00}));
  send_all(fd, frame(1, {0x05, 0, 0, 0xFF, 0x00}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x05, 0, 0, 0xFF, 0x00}));  // echo
  // Until taken, coil 0 reads back 1.
  send_all(fd, frame(1, {0x01, 0, 0, 0, 1}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x01, 1, 0x01}));
  EXPECT_TRUE(server_->take_requests().latch_clear_request);
  EXPECT_FALSE(server_->take_requests().latch_clear_request);
  send_all(fd, frame(1, {0x01, 0, 0, 0, 1}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x01, 1, 0x00}));
  close(fd);
}

TEST_F(PRO05_ModbusServer, CoilZeroReadsOneWhileTheControllerHoldsARequest) {
  const int fd = connect_to(server_->port());
  image_.latch_clear_request = 1;  // taken from the server, not yet consumed by a tick
  send_all(fd, frame(1, {0x01, 0, 0, 0, 1}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x01, 1, 0x01}));
  image_.latch_clear_request = 0;  // consumed
  send_all(fd, frame(1, {0x01, 0, 0, 0, 1}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x01, 1, 0x00}));
  EXPECT_FALSE(server_->take_requests().latch_clear_request);  // reading requests nothing
  close(fd);
}

TEST_F(PRO05_ModbusServer, AnExceptionIsAnsweredAndTheConnectionKeepsServing) {
  const int fd = connect_to(server_->port());
  send_all(fd, frame(1, {0x04, 0, 0, 0, 0}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x84, 0x03}));
  send_all(fd, frame(1, {0x04, 0, 2, 0, 1}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x04, 2, 0, 55}));
  close(fd);
}

TEST_F(PRO05_ModbusServer, ATruncatedFrameClosesOnlyItsConnectionAfterTheFrameTimeout) {
  const int stalled = connect_to(server_->port());
  const int healthy = connect_to(server_->port());
  send_all(stalled, Bytes{0x00, 0x01, 0x00, 0x00, 0x00, 0x06, 0x01, 0x04});  // 8 of 12 bytes
  for (std::uint32_t i = 0; i <= config_.frame_timeout_ticks + 1; ++i) server_->on_tick(image_);
  EXPECT_EQ(server_->counters().count(ModbusReason::truncated_frame), 1U);
  std::uint8_t b = 0;
  EXPECT_EQ(recv(stalled, &b, 1, 0), 0);  // EOF: the server closed it
  send_all(healthy, frame(1, {0x04, 0, 1, 0, 1}));
  EXPECT_EQ(tick_until_reply(*server_, image_, healthy), frame(1, {0x04, 2, 0, 245}));
  close(stalled);
  close(healthy);
}

TEST_F(PRO05_ModbusServer, AFifthClientIsRefusedAndTheFourKeepTheirSlots) {
  std::vector<int> fds;
  for (std::size_t i = 0; i <= kModbusMaxConnections; ++i) fds.push_back(connect_to(server_->port()));
  for (int i = 0; i < 3; ++i) server_->on_tick(image_);
  EXPECT_EQ(server_->open_connections(), kModbusMaxConnections);
  EXPECT_EQ(server_->counters().connections_refused, 1U);
  send_all(fds[0], frame(1, {0x04, 0, 4, 0, 1}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fds[0]), frame(1, {0x04, 2, 0, 1}));
  for (const int fd : fds) close(fd);
}

TEST_F(PRO05_ModbusServer, AtMostEightFramesAreHandledPerTickAndTheRestWait) {
  const int fd = connect_to(server_->port());
  const Bytes burst = repeated(frame(1, {0x04, 0, 0, 0, 1}), 20);
  send_all(fd, burst);  // 240 bytes: all of it fits in the connection's 260-byte buffer
  server_->on_tick(image_);
  EXPECT_EQ(server_->counters().count(ModbusReason::ok), kModbusMaxRequestsPerTick);
  server_->on_tick(image_);
  EXPECT_EQ(server_->counters().count(ModbusReason::ok), 2 * kModbusMaxRequestsPerTick);
  server_->on_tick(image_);
  EXPECT_EQ(server_->counters().count(ModbusReason::ok), 20U);
  EXPECT_EQ(server_->counters().count(ModbusReason::truncated_frame), 0U);
  close(fd);
}

TEST_F(PRO05_ModbusServer, AClientThatNeverReadsItsRepliesIsDisconnectedNotWaitedFor) {
  // A small receive buffer and no reads: the replies pile up until the server's socket is
  // full; the server then drops the connection instead of waiting (send_failed).
  const int greedy = socket(AF_INET, SOCK_STREAM, 0);
  const int small = 4096;
  setsockopt(greedy, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(server_->port());
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(connect(greedy, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  const Bytes burst = repeated(frame(1, {0x04, 0, 0, 0, 6}), kModbusMaxRequestsPerTick);
  int ticks = 0;
  while (server_->counters().count(ModbusReason::send_failed) == 0 && ticks < 200000) {
    if (send(greedy, burst.data(), burst.size(), MSG_NOSIGNAL | MSG_DONTWAIT) < 0) break;
    server_->on_tick(image_);
    ++ticks;
  }
  EXPECT_EQ(server_->counters().count(ModbusReason::send_failed), 1U);
  EXPECT_EQ(server_->open_connections(), 0U);
  const int fd = connect_to(server_->port());
  send_all(fd, frame(1, {0x04, 0, 0, 0, 6}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), kImageReply);
  close(fd);
  close(greedy);
}

TEST_F(PRO05_ModbusServer, ServingAllocatesNothingAfterStart) {
  const int fd = connect_to(server_->port());
  const Bytes read = frame(1, {0x04, 0, 0, 0, 6});
  const Bytes bad = frame(1, {0x07});
  g_allocations = 0;
  g_counting = true;
  for (int i = 0; i < 500; ++i) {
    send(fd, (i % 2 ? bad : read).data(), (i % 2 ? bad : read).size(), 0);
    server_->on_tick(image_);
    std::uint8_t buf[300];
    (void)recv(fd, buf, sizeof buf, MSG_DONTWAIT);
    (void)server_->take_requests();
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0U);
  EXPECT_GT(server_->counters().count(ModbusReason::ok), 0U);
  close(fd);
}

TEST_F(PRO05_ModbusServer, RandomFramesNeverStopItServingACleanClient) {
  // 3,000 seeded random frames: valid MBAP headers around random PDUs of random length, with
  // random unit and protocol ids now and then, and raw garbage. Whatever they do to their own
  // connection (answered, discarded, closed), a clean client is served correctly afterwards.
  std::mt19937 rng(20261129U);
  int fd = connect_to(server_->port());
  for (int i = 0; i < 3000; ++i) {
    constexpr std::uint8_t kServed[] = {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x0F, 0x10};
    const std::size_t pdu_size = rng() % 2 ? 5 : 1 + rng() % 12;
    Bytes f{static_cast<std::uint8_t>(i >> 8),
            static_cast<std::uint8_t>(i),
            0,
            0,
            0,
            static_cast<std::uint8_t>(pdu_size + 1),
            static_cast<std::uint8_t>(rng() % 4 == 0 ? rng() : 1)};
    // Function: half the time one the server implements; other bytes mostly small (so
    // addresses and quantities are often in range), sometimes anything.
    for (std::size_t k = 0; k < pdu_size; ++k) {
      const std::uint32_t b = k == 0 ? (rng() % 2 ? kServed[rng() % 8] : rng()) : (rng() % 4 ? rng() % 3 : rng());
      f.push_back(static_cast<std::uint8_t>(b));
    }
    if (rng() % 50 == 0) f[3] = 1;                                  // protocol id 1
    if (rng() % 100 == 0) f[5] = static_cast<std::uint8_t>(rng());  // any length byte
    if (send(fd, f.data(), f.size(), MSG_NOSIGNAL) < 0) {
      close(fd);
      fd = connect_to(server_->port());
      continue;
    }
    server_->on_tick(image_);
    std::uint8_t buf[300];
    if (recv(fd, buf, sizeof buf, MSG_DONTWAIT) == 0 || server_->open_connections() == 0) {
      close(fd);  // the server closed it (framing lost): a new connection
      fd = connect_to(server_->port());
    }
  }
  close(fd);
  const int clean = connect_to(server_->port());
  send_all(clean, frame(1, {0x04, 0, 0, 0, 6}));
  EXPECT_EQ(tick_until_reply(*server_, image_, clean), kImageReply);
  const ModbusServerCounters& c = server_->counters();
  std::uint32_t handled = 0;
  for (const std::uint32_t n : c.frames) handled += n;
  EXPECT_GE(handled, 2500U);  // the rest were glued into streams that lost their framing
  // Every rule of the check was exercised (a reply that cannot be sent needs a full socket;
  // the write guard's refusals need a client off the allow-list or a well-formed write to
  // coil 0, which random frames rarely are: they have tests of their own below).
  for (std::size_t r = 0; r < kModbusReasonCount; ++r) {
    const auto reason = static_cast<ModbusReason>(r);
    if (reason != ModbusReason::send_failed && reason != ModbusReason::write_not_allowed &&
        reason != ModbusReason::write_not_armed) {
      EXPECT_GT(c.frames[r], 0U) << "reason " << r;
    }
  }
  close(clean);
}

TEST_F(PRO05_ModbusServer, StopDisconnectsClientsAndClosesTheListeningSocket) {
  const int fd = connect_to(server_->port());
  server_->on_tick(image_);
  ASSERT_EQ(server_->open_connections(), 1U);
  const std::uint16_t port = server_->port();
  EXPECT_EQ(server_->stop(), UnitStatus::stopped);
  EXPECT_EQ(server_->open_connections(), 0U);
  std::uint8_t b = 0;
  EXPECT_EQ(recv(fd, &b, 1, 0), 0);  // EOF
  EXPECT_LT(connect_to(port), 0);    // nobody listens any more
  server_->on_tick(image_);          // a tick after stop serves nothing and does not crash
  EXPECT_EQ(server_->status(), UnitStatus::stopped);
  close(fd);
}

// Issue 31 item 6: writes that change safety state only from an allow-listed client and
// only within the arm window of the write-enable coil; refusals answered with exception 01
// and counted.
TEST_F(PRO05_ModbusServer, AClearWithoutTheWriteEnableIsRefusedWithExceptionOneAndCounted) {
  const int fd = connect_to(server_->port());
  send_all(fd, frame(1, {0x05, 0, 0, 0xFF, 0x00}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x85, 0x01}));
  send_all(fd, frame(1, {0x0F, 0, 0, 0, 2, 1, 0x03}));  // clear and enable in one frame: no handshake
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x8F, 0x01}));
  EXPECT_FALSE(server_->take_requests().latch_clear_request);
  EXPECT_EQ(server_->counters().count(ModbusReason::write_not_armed), 2U);
  close(fd);
}

TEST_F(PRO05_ModbusServer, TheWriteEnableArmsOneWriteOfTheSameConnectionForTheWindow) {
  const int fd = connect_to(server_->port());
  const int other = connect_to(server_->port());
  send_all(fd, frame(1, {0x05, 0, 1, 0xFF, 0x00}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x05, 0, 1, 0xFF, 0x00}));
  send_all(fd, frame(1, {0x01, 0, 1, 0, 1}));  // coil 1 reads back the arm
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x01, 1, 0x01}));
  send_all(other, frame(1, {0x05, 0, 0, 0xFF, 0x00}));  // another connection is not armed
  EXPECT_EQ(tick_until_reply(*server_, image_, other), frame(1, {0x85, 0x01}));
  send_all(fd, frame(1, {0x05, 0, 0, 0xFF, 0x00}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x05, 0, 0, 0xFF, 0x00}));
  EXPECT_TRUE(server_->take_requests().latch_clear_request);
  send_all(fd, frame(1, {0x05, 0, 0, 0xFF, 0x00}));  // the arm was consumed
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x85, 0x01}));
  // An arm expires after arm_window_ticks.
  send_all(fd, frame(1, {0x05, 0, 1, 0xFF, 0x00}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x05, 0, 1, 0xFF, 0x00}));
  for (std::uint32_t i = 0; i < config_.arm_window_ticks; ++i) server_->on_tick(image_);
  send_all(fd, frame(1, {0x05, 0, 0, 0xFF, 0x00}));
  EXPECT_EQ(tick_until_reply(*server_, image_, fd), frame(1, {0x85, 0x01}));
  EXPECT_FALSE(server_->take_requests().latch_clear_request);
  EXPECT_EQ(server_->counters().count(ModbusReason::write_not_armed), 3U);
  close(fd);
  close(other);
}

TEST(PRO05_ModbusWriteAllowList, AClientNotOnTheAllowListCanReadButNotWrite) {
  ModbusServerConfig config;
  config.port = 0;
  config.write_allowlist[0] = 0x7F000002;  // 127.0.0.2 only: the test's 127.0.0.1 is not on it
  AoModbusServer server(config);
  ASSERT_EQ(server.start(), UnitStatus::ready);
  ProcessImage image;
  image.voltage_dv = 240;
  const int fd = connect_to(server.port());
  send_all(fd, frame(1, {0x04, 0, 1, 0, 1}));
  EXPECT_EQ(tick_until_reply(server, image, fd), frame(1, {0x04, 2, 0, 240}));
  send_all(fd, frame(1, {0x05, 0, 1, 0xFF, 0x00}));  // not even the write enable
  EXPECT_EQ(tick_until_reply(server, image, fd), frame(1, {0x85, 0x01}));
  send_all(fd, frame(1, {0x05, 0, 0, 0xFF, 0x00}));
  EXPECT_EQ(tick_until_reply(server, image, fd), frame(1, {0x85, 0x01}));
  EXPECT_FALSE(server.take_requests().latch_clear_request);
  EXPECT_EQ(server.counters().count(ModbusReason::write_not_allowed), 2U);
  close(fd);
}

}  // namespace
