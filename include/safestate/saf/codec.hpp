// SPDX-License-Identifier: Apache-2.0
// The little-endian wire format of the nine messages (SAF-03, design §10).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "safestate/saf/decode_error.hpp"
#include "safestate/saf/message.hpp"

namespace safestate::saf {

inline constexpr std::size_t kHeaderSize = 10;   // u64 id + u16 payload length
inline constexpr std::size_t kMaxDatagram = 64;  // larger datagrams are OVERSIZED

/// One encoded message (fixed storage, no heap).
struct Encoded {
  std::array<std::uint8_t, kMaxDatagram> bytes{};
  std::size_t size = 0;
};

/// A decoded message, or the reason it was rejected (`error != None`).
struct DecodeResult {
  Message message{};
  DecodeError error = DecodeError::None;
  [[nodiscard]] bool ok() const noexcept { return error == DecodeError::None; }
};

/// Decodes one datagram of `size` bytes (any of the nine types). Reads no byte past
/// `min(size, kMaxDatagram)`; never throws.
[[nodiscard]] DecodeResult decode(const std::uint8_t* data, std::size_t size) noexcept;

/// Encodes a message (its fields must be in range; out-of-range enum values are written
/// as they are, which lets tests build FIELD_RANGE cases).
[[nodiscard]] Encoded encode(const Message& m) noexcept;

}  // namespace safestate::saf
