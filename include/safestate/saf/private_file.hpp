// SPDX-License-Identifier: Apache-2.0
// Reading a file only its owner may read (the HMAC key, the replay state): opened once,
// checked on the open descriptor (a regular file, no group or other permission bits), so
// it cannot be swapped between the check and the read, and read into a bounded buffer.
// No heap. Each loader maps the status to its own reasons.
#pragma once

#include <cstddef>
#include <cstdint>

namespace safestate::saf {

enum class PrivateFileStatus : std::uint8_t {
  Ok,
  Missing,      // no such file (ENOENT)
  CannotOpen,   // exists but cannot be opened or read (errno in the result)
  NotRegular,   // a directory, a device, ...
  Permissions,  // group or others have any permission bit (mode in the result)
  TooLong,      // more bytes than the buffer holds
};

struct PrivateFileRead {
  PrivateFileStatus status = PrivateFileStatus::Ok;
  int error_number = 0;    // errno, for Missing and CannotOpen
  std::uint32_t mode = 0;  // the permission bits, once the file was opened
  std::size_t size = 0;    // bytes read into the buffer, for Ok
};

/// Reads all of `path` into `buffer` (at most `capacity` bytes; a longer file is TooLong).
[[nodiscard]] PrivateFileRead read_private_file(const char* path, char* buffer, std::size_t capacity) noexcept;

}  // namespace safestate::saf
