// SPDX-License-Identifier: Apache-2.0
// The intake of the deployed service (design §14, §15): decides, before the core sees a
// datagram, whether it comes from the sender its type must come from, is fresh, and (where
// a key is configured) authentic, on the client socket and on the subsystem link. Accepted datagrams are passed on
// unchanged and in order; every rejected one is counted under its reason and listed for the log.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "safestate/saf/estop_extension.hpp"
#include "safestate/saf/inbound_batch.hpp"
#include "safestate/saf/intake_reason.hpp"
#include "safestate/saf/link_auth.hpp"
#include "safestate/saf/message_id.hpp"
#include "safestate/saf/sequence_file.hpp"
#include "safestate/saf/source.hpp"

namespace safestate::saf {

struct IntakeConfig {
  Peer client{};  // the Safety Client's address and port
  std::uint32_t client_component_id = 0;
  Peer subsystem{};                  // the subsystem's (Subsystem State service) address and port
  bool require_sequence = true;      // false: the seed's Set Estop is accepted too (no freshness)
  MacKey key{};                      // present: only the Authenticated form is accepted, and
                                     // only sealed datagrams on the subsystem socket (§15)
  std::uint64_t replay_window = 64;  // separates *_REPLAY from *_STALE (design §14, §15)
};

struct IntakeRejection {
  IntakeReason reason = IntakeReason::None;
  Source source{};
  bool decoded = false;  // `id` is meaningful
  MessageId id = MessageId::SetEstop;
};

/// The rejections of one cycle (at most one per datagram of the batch).
struct IntakeCycle {
  std::array<IntakeRejection, kMaxInboundPerCycle> rejected{};
  std::size_t count = 0;
};

struct IntakeCounters {
  std::uint64_t accepted = 0;
  std::array<std::uint64_t, kIntakeReasonCount> rejected{};  // indexed by IntakeReason
  [[nodiscard]] std::uint64_t rejected_total() const noexcept {
    std::uint64_t n = 0;
    for (std::uint64_t r : rejected) n += r;
    return n;
  }
  [[nodiscard]] std::uint64_t of(IntakeReason r) const noexcept { return rejected[static_cast<std::size_t>(r)]; }
};

class Intake {
 public:
  explicit Intake(const IntakeConfig& config) noexcept : config_(config) { link_.window = config.replay_window; }

  /// Copies the accepted datagrams of `in` into `out` (cleared first). `overflow`: the
  /// client socket dropped datagrams or still holds a backlog this cycle, so a Set Estop
  /// may have been lost: a clear one is then no evidence that the E-stop is released.
  IntakeCycle filter(const InboundBatch& in, bool overflow, InboundBatch& out) noexcept;

  /// The verdict on one datagram (updates the sequence state when it is an accepted Set
  /// Estop or an authentic fresh link datagram, and the counters).
  IntakeRejection judge(const Datagram& d, const Source& from, bool overflow) noexcept {
    Datagram opened{};
    return judge(d, from, overflow, opened);
  }
  /// As above; `opened` gets the datagram the core is to see (without the link trailer).
  IntakeRejection judge(const Datagram& d, const Source& from, bool overflow, Datagram& opened) noexcept;

  /// The highest accepted sequences restored from the sequence file (design §15), before
  /// the first cycle: a Set Estop or sealed subsystem message at or below them is stale.
  void restore(const SequenceState& s) noexcept;
  /// The highest accepted sequences, for the sequence file (`service` left 0).
  [[nodiscard]] SequenceState sequences() const noexcept;

  [[nodiscard]] const IntakeCounters& counters() const noexcept { return counters_; }
  [[nodiscard]] const IntakeConfig& config() const noexcept { return config_; }
  /// The highest sequence number accepted so far (0 with none).
  [[nodiscard]] std::uint64_t highest_sequence() const noexcept { return highest_; }

 private:
  [[nodiscard]] IntakeReason judge_estop(const Datagram& d, const Message& m, const Source& from,
                                         bool overflow) noexcept;

  IntakeConfig config_;
  IntakeCounters counters_{};
  bool have_sequence_ = false;
  std::uint64_t highest_ = 0;
  LinkReceiver link_{};  // the subsystem's sealed messages (with a key)
};

}  // namespace safestate::saf
