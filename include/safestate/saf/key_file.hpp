// SPDX-License-Identifier: Apache-2.0
// The HMAC key of the Set Estop authentication (design §14): read from a file only its
// owner can read, as hexadecimal text, 16 to 64 bytes. Anything else is refused with a
// reason: a safety service does not run with a key others could have read or replaced.
#pragma once

#include <cstdint>
#include <string_view>

#include "safestate/saf/estop_extension.hpp"

namespace safestate::saf {

enum class KeyFileError : std::uint8_t {
  None,
  CannotOpen,   // missing or unreadable (errno in the result)
  NotRegular,   // a directory, a device, ...
  Permissions,  // group or others have any permission (must be 0600 or 0400)
  NotHex,       // a character that is not a hex digit (surrounding whitespace is allowed)
  BadLength,    // an odd number of hex digits, or fewer than 16 / more than 64 bytes
};

[[nodiscard]] constexpr std::string_view to_string(KeyFileError e) noexcept {
  switch (e) {
    case KeyFileError::None: return "none";
    case KeyFileError::CannotOpen: return "cannot be opened";
    case KeyFileError::NotRegular: return "is not a regular file";
    case KeyFileError::Permissions: return "is readable or writable by group or others (must be mode 0600 or 0400)";
    case KeyFileError::NotHex: return "must hold the key as hexadecimal digits";
    case KeyFileError::BadLength: return "must hold 16 to 64 bytes (32 to 128 hex digits)";
  }
  return "?";
}

inline constexpr std::size_t kMinKeyBytes = 16;

struct KeyFileResult {
  KeyFileError error = KeyFileError::None;
  int error_number = 0;    // errno for CannotOpen
  std::uint32_t mode = 0;  // the file's permission bits, for Permissions
  MacKey key{};
};

/// Reads the key from `path` (checks the mode on the opened file, so it cannot be swapped
/// between the check and the read).
[[nodiscard]] KeyFileResult load_key_file(const char* path) noexcept;

}  // namespace safestate::saf
