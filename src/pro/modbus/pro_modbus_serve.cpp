// pro_modbus_serve: ao_modbus_server on 127.0.0.1 in a plain tick loop, serving a fixed
// process image given on the command line. The pytest tests start it as a subprocess with
// --port 0 and drive it with a real Modbus client (tests/python/test_pro_modbus_server.py).
//
// Prints `listening 127.0.0.1:<port>` once bound, `clear request taken at tick <n>` for
// every latch clear request handed over, and on SIGTERM/SIGINT stops the server (socket
// closed, clients disconnected) and prints `stopped` and the frame counters.
#include <arpa/inet.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>

#include "safestate/pro/ao_modbus_server.hpp"

namespace {

volatile std::sig_atomic_t g_stop = 0;
void on_signal(int) { g_stop = 1; }

constexpr const char* kUsage =
    "usage: pro_modbus_serve [--port N] [--unit-id N] [--tick-ms N] [--frame-timeout-ticks N]\n"
    "                        [--idle-timeout-ticks N] [--temperature-c N] [--voltage-dv N]\n"
    "                        [--fan-percent N] [--protection-state N] [--supervisor-state N]\n"
    "                        [--last-clear-result N] [--allow-writes-from A.B.C.D]...\n"
    "                        [--arm-window-ticks N]\n";

constexpr const char* kReasonNames[] = {"ok",
                                        "unsupported_function",
                                        "length_mismatch",
                                        "bad_quantity",
                                        "bad_byte_count",
                                        "bad_coil_value",
                                        "address_out_of_range",
                                        "wrong_unit_id",
                                        "wrong_protocol_id",
                                        "reserved_function",
                                        "bad_mbap_length",
                                        "truncated_frame",
                                        "send_failed",
                                        "write_not_allowed",
                                        "write_not_armed"};
static_assert(sizeof kReasonNames / sizeof kReasonNames[0] == safestate::pro::kModbusReasonCount);

// Parses `text` as an integer in [lo, hi]; false (with a one-line error) otherwise.
bool parse(const char* option, const char* text, long lo, long hi, long& out) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text, &end, 10);
  if (errno != 0 || end == text || *end != '\0' || v < lo || v > hi) {
    std::fprintf(stderr, "pro_modbus_serve: %s: expected an integer in %ld..%ld, got '%s'\n", option, lo, hi, text);
    return false;
  }
  out = v;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace safestate::pro;
  ModbusServerConfig config;
  ProcessImage image;
  long tick_ms = 100;
  std::size_t allow_given = 0;
  for (int i = 1; i < argc; ++i) {
    const char* opt = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "pro_modbus_serve: %s: missing value\n%s", opt, kUsage);
      return 2;
    }
    const char* val = argv[++i];
    long v = 0;
    bool ok = true;
    if (!std::strcmp(opt, "--port")) {
      ok = parse(opt, val, 0, 65535, v) && ((config.port = static_cast<std::uint16_t>(v)), true);
    } else if (!std::strcmp(opt, "--unit-id")) {
      ok = parse(opt, val, 1, 247, v) && ((config.unit_id = static_cast<std::uint8_t>(v)), true);
    } else if (!std::strcmp(opt, "--tick-ms")) {
      ok = parse(opt, val, 1, 10000, tick_ms);
    } else if (!std::strcmp(opt, "--frame-timeout-ticks")) {
      ok = parse(opt, val, 1, 1000000, v) && ((config.frame_timeout_ticks = static_cast<std::uint32_t>(v)), true);
    } else if (!std::strcmp(opt, "--idle-timeout-ticks")) {
      ok = parse(opt, val, 1, 1000000, v) && ((config.idle_timeout_ticks = static_cast<std::uint32_t>(v)), true);
    } else if (!std::strcmp(opt, "--temperature-c")) {
      ok = parse(opt, val, std::numeric_limits<std::int16_t>::min(), std::numeric_limits<std::int16_t>::max(), v) &&
           ((image.temperature_c = static_cast<std::int16_t>(v)), true);
    } else if (!std::strcmp(opt, "--voltage-dv")) {
      ok = parse(opt, val, 0, 65535, v) && ((image.voltage_dv = static_cast<std::uint16_t>(v)), true);
    } else if (!std::strcmp(opt, "--fan-percent")) {
      ok = parse(opt, val, 0, 100, v) && ((image.fan_command_percent = static_cast<std::uint16_t>(v)), true);
    } else if (!std::strcmp(opt, "--protection-state")) {
      ok = parse(opt, val, 0, 1, v) && ((image.protection_state = static_cast<std::uint16_t>(v)), true);
    } else if (!std::strcmp(opt, "--supervisor-state")) {
      ok = parse(opt, val, 0, 4, v) && ((image.supervisor_state = static_cast<std::uint16_t>(v)), true);
    } else if (!std::strcmp(opt, "--allow-writes-from")) {
      in_addr a{};
      if (inet_pton(AF_INET, val, &a) != 1 || allow_given >= config.write_allowlist.size()) {
        std::fprintf(stderr, "pro_modbus_serve: %s: expected an IPv4 address (at most %zu), got '%s'\n", opt,
                     config.write_allowlist.size(), val);
        return 2;
      }
      config.write_allowlist[allow_given++] = ntohl(a.s_addr);
      config.write_allowlist_size = allow_given;
    } else if (!std::strcmp(opt, "--arm-window-ticks")) {
      ok = parse(opt, val, 1, 1000000, v) && ((config.arm_window_ticks = static_cast<std::uint32_t>(v)), true);
    } else if (!std::strcmp(opt, "--last-clear-result")) {
      ok = parse(opt, val, 0, 3, v) && ((image.last_clear_result = static_cast<std::uint16_t>(v)), true);
    } else {
      std::fprintf(stderr, "pro_modbus_serve: unknown option '%s'\n%s", opt, kUsage);
      return 2;
    }
    if (!ok) return 2;
  }

  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);
  AoModbusServer server(config);
  if (server.start() != UnitStatus::ready) {
    std::fprintf(stderr, "pro_modbus_serve: cannot listen on 127.0.0.1:%u: %s\n", config.port, std::strerror(errno));
    return 1;
  }
  std::printf("listening 127.0.0.1:%u\n", server.port());
  std::fflush(stdout);

  const timespec period{tick_ms / 1000, (tick_ms % 1000) * 1000000L};
  for (std::uint32_t tick = 1; g_stop == 0; ++tick) {
    server.on_tick(image);
    if (server.take_requests().latch_clear_request) {
      std::printf("clear request taken at tick %u\n", tick);
      std::fflush(stdout);
    }
    nanosleep(&period, nullptr);
  }

  const std::size_t open = server.open_connections();
  if (server.stop() != UnitStatus::stopped) return 1;
  const ModbusServerCounters& c = server.counters();
  std::printf("stopped: %zu client connection(s) closed, accepted %u, refused %u, idle timeouts %u\n", open,
              c.connections_accepted, c.connections_refused, c.idle_timeouts);
  for (std::size_t r = 0; r < kModbusReasonCount; ++r) std::printf("frames %s %u\n", kReasonNames[r], c.frames[r]);
  return 0;
}
