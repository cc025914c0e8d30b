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

/// One received datagram. `size` is its real length; at most kMaxDatagram bytes are kept
/// (a longer one is rejected as OVERSIZED without reading the rest).
struct Datagram {
  std::array<std::uint8_t, kMaxDatagram> bytes{};
  std::size_t size = 0;
};

struct InboundBatch {
  std::array<Datagram, kMaxInboundPerCycle> items{};
  /// The sender of items[i] (design §14); the core ignores it, the intake checks it.
  std::array<Source, kMaxInboundPerCycle> sources{};
  std::size_t count = 0;

  /// Appends a copy of the datagram; false (nothing stored) when the batch is full.
  [[nodiscard]] bool push(const std::uint8_t* data, std::size_t size, const Source& from = {}) noexcept;
  /// Appends an encoded message; false when the batch is full.
  [[nodiscard]] bool push(const Encoded& e, const Source& from = {}) noexcept {
    return push(e.bytes.data(), e.size, from);
  }
  [[nodiscard]] bool full() const noexcept { return count == items.size(); }
  void clear() noexcept { count = 0; }
};

}  // namespace safestate::saf
