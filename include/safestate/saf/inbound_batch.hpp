// SPDX-License-Identifier: Apache-2.0
// The datagrams received for one cycle: fixed storage, bounded count (design §2, §9).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "safestate/saf/codec.hpp"
#include "safestate/saf/source.hpp"

namespace safestate::saf {

inline constexpr std::size_t kMaxInboundPerCycle = 16;

/// Who sent a datagram, as the intake's sender binding tells the core (design §5): the
/// configured Safety Client, the configured subsystem, or any other source.
enum class Sender : std::uint8_t { Client, Subsystem, Other };

/// One received datagram. `size` is its real length; at most kMaxDatagram bytes are kept
/// (a longer one is rejected as OVERSIZED without reading the rest). `from` and `fresh` are
/// the transport's intake verdict: the sender, and whether its sequence number (Set Estop)
/// is inside the replay window. The service accepts a message only from the peer of its
/// kind and only fresh; an untagged datagram counts as from another source (fail safe).
struct Datagram {
  std::array<std::uint8_t, kMaxDatagram> bytes{};
  std::size_t size = 0;
  Sender from = Sender::Other;
  bool fresh = true;
};

struct InboundBatch {
  std::array<Datagram, kMaxInboundPerCycle> items{};
  /// The sender of items[i] (design §14); the core ignores it, the intake checks it.
  std::array<Source, kMaxInboundPerCycle> sources{};
  std::size_t count = 0;

  /// Appends a copy of the datagram with the core's tag (the intake's verdict: sender
  /// and freshness); false (nothing stored) when the batch is full.
  [[nodiscard]] bool push(const std::uint8_t* data, std::size_t size, Sender from = Sender::Other,
                          bool fresh = true) noexcept {
    return push(data, size, Source{}, from, fresh);
  }
  /// Appends a received datagram with the transport's record of its source, untagged for
  /// the core until the intake has judged it (Intake::filter).
  [[nodiscard]] bool push(const std::uint8_t* data, std::size_t size, const Source& source) noexcept {
    return push(data, size, source, Sender::Other, true);
  }
  [[nodiscard]] bool push(const std::uint8_t* data, std::size_t size, const Source& source, Sender from,
                          bool fresh) noexcept;
  /// Appends an encoded message; false when the batch is full.
  [[nodiscard]] bool push(const Encoded& e, Sender from = Sender::Other, bool fresh = true) noexcept {
    return push(e.bytes.data(), e.size, from, fresh);
  }
  [[nodiscard]] bool push(const Encoded& e, const Source& source) noexcept {
    return push(e.bytes.data(), e.size, source);
  }
  [[nodiscard]] bool full() const noexcept { return count == items.size(); }
  void clear() noexcept { count = 0; }
};

}  // namespace safestate::saf
