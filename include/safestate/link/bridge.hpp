// SPDX-License-Identifier: Apache-2.0
// The non-real-time side of the operator link (design §11): a WebSocket/HTTP server on
// 127.0.0.1 (Boost.Beast) in its own thread. It turns JSON requests (schema:
// docs/operator-link-schema.json) into Commands for the ControlLoop's queue, answers each
// with its result once the cycle has popped it, broadcasts the status snapshot, enforces
// the access control (observers, one controlling client with a token) and serves the
// operator panel's static files. It allocates and may throw inside itself: it never runs on
// the control thread, and the control thread never waits on it.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "safestate/link/control_loop.hpp"

namespace safestate::link {

/// Version of docs/operator-link-schema.json that the bridge speaks.
inline constexpr int kLinkSchemaVersion = 1;

struct BridgeOptions {
  std::string token;                  ///< the control token (read_token_file)
  std::filesystem::path www;          ///< static files of the panel (may be empty)
  unsigned short port{0};             ///< 0: an ephemeral port (see Bridge::port)
  std::size_t max_frame_bytes{4096};  ///< larger frames close the socket (1009)
  std::size_t max_clients{256};
  std::size_t max_queued_frames{32};  ///< per client: status frames beyond are dropped
  std::chrono::milliseconds status_period{50};
  std::chrono::milliseconds control_lease{1000};  ///< control released without heartbeat
};

/// Every refusal and error the bridge reports, counted (also sent in each status frame).
struct BridgeCounters {
  std::atomic<std::uint64_t> requests{0};
  std::atomic<std::uint64_t> malformed_json{0};
  std::atomic<std::uint64_t> unknown_type{0};
  std::atomic<std::uint64_t> bad_field{0};
  std::atomic<std::uint64_t> frame_too_large{0};
  std::atomic<std::uint64_t> observer_commands_refused{0};
  std::atomic<std::uint64_t> control_refused{0};
  std::atomic<std::uint64_t> queue_full{0};
  std::atomic<std::uint64_t> status_frames_dropped{0};
  std::atomic<std::uint64_t> slow_consumers_closed{0};
  std::atomic<std::uint64_t> clients_refused{0};
  std::atomic<std::uint64_t> results_lost{0};
  std::atomic<std::uint64_t> heartbeats{0};
  std::atomic<std::uint64_t> control_lease_expired{0};
  std::atomic<std::uint64_t> reads_paused{0};  ///< backpressure: a client's replies piled up
  std::atomic<std::uint64_t> busy{0};          ///< the controller's requests not executed while its answers piled up
  std::atomic<std::uint64_t> clients{0};       ///< connected WebSocket clients now
};

/// Reads the control token: the first line of `path`, which must be a regular file readable
/// by its owner only (mode 0600 or stricter). FALSE with a one-line `error` otherwise.
[[nodiscard]] bool read_token_file(const std::filesystem::path& path, std::string& token, std::string& error);

class Bridge {
 public:
  /// Binds 127.0.0.1:`options.port` at once (throws std::system_error if it cannot).
  Bridge(ControlLoop& loop, BridgeOptions options);
  ~Bridge();
  Bridge(const Bridge&) = delete;
  Bridge& operator=(const Bridge&) = delete;
  Bridge(Bridge&&) = delete;
  Bridge& operator=(Bridge&&) = delete;

  [[nodiscard]] unsigned short port() const noexcept;
  /// Serves until stop(); call from the bridge thread.
  void run();
  /// Thread-safe.
  void stop();
  [[nodiscard]] const BridgeCounters& counters() const noexcept;

  struct Impl;  ///< the bridge's state (bridge.cpp); public only for its session classes

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace safestate::link
