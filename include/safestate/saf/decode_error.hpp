// SPDX-License-Identifier: Apache-2.0
// Why a datagram was rejected by the codec (SAF-03, design §10).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate::saf {

enum class DecodeError : std::uint8_t {
  None = 0,
  Truncated,
  Oversized,
  TrailingBytes,
  UnknownId,
  BadLength,
  FieldRange,
  NotIncoming,
};

inline constexpr std::size_t kDecodeErrorCount = 8;

[[nodiscard]] constexpr std::string_view to_string(DecodeError e) noexcept {
  switch (e) {
    case DecodeError::None: return "NONE";
    case DecodeError::Truncated: return "TRUNCATED";
    case DecodeError::Oversized: return "OVERSIZED";
    case DecodeError::TrailingBytes: return "TRAILING_BYTES";
    case DecodeError::UnknownId: return "UNKNOWN_ID";
    case DecodeError::BadLength: return "BAD_LENGTH";
    case DecodeError::FieldRange: return "FIELD_RANGE";
    case DecodeError::NotIncoming: return "NOT_INCOMING";
  }
  return "?";
}

}  // namespace safestate::saf
