// SPDX-License-Identifier: Apache-2.0
// The service's replay state across a restart (design §15): the highest accepted Set
// Estop sequence, the highest accepted sequence of the subsystem's sealed messages, and
// the next sequence of our own sealed messages, kept in `[security] sequence_file`. The
// file is created 0600 and replaced atomically (temporary file, fsync, rename, fsync of
// the folder) after each cycle in which a value moved, outside the scan cycle; at start it
// is read, and anything but the exact format is refused (never a silent reset to 0).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace safestate::saf {

struct SequenceState {
  bool have_estop = false;  // false: no Set Estop accepted yet ("none" in the file)
  std::uint64_t estop = 0;
  bool have_subsystem = false;
  std::uint64_t subsystem = 0;
  std::uint64_t service = 0;  // the next sequence the service seals its messages with
  friend bool operator==(const SequenceState& a, const SequenceState& b) noexcept {
    return a.have_estop == b.have_estop && a.estop == b.estop && a.have_subsystem == b.have_subsystem &&
           a.subsystem == b.subsystem && a.service == b.service;
  }
  friend bool operator!=(const SequenceState& a, const SequenceState& b) noexcept { return !(a == b); }
};

enum class SequenceFileError : std::uint8_t {
  None,
  Missing,      // no such file: the first start (the caller decides; serve creates it)
  CannotOpen,   // exists but cannot be read (errno in the result)
  NotRegular,   // a directory, a device, ...
  Permissions,  // group or others have any permission (anyone who can write it resets the window)
  TooLong,      // more bytes than the format can have
  BadFormat,    // `line` and `expected` say where and what
  CannotWrite,  // store: the temporary file, its fsync, the rename or the folder's fsync failed (errno)
};

[[nodiscard]] constexpr std::string_view to_string(SequenceFileError e) noexcept {
  switch (e) {
    case SequenceFileError::None: return "none";
    case SequenceFileError::Missing: return "does not exist";
    case SequenceFileError::CannotOpen: return "cannot be opened";
    case SequenceFileError::NotRegular: return "is not a regular file";
    case SequenceFileError::Permissions:
      return "is readable or writable by group or others (must be mode 0600 or 0400)";
    case SequenceFileError::TooLong: return "is longer than a sequence file can be (at most 128 bytes)";
    case SequenceFileError::BadFormat: return "is not a sequence file";
    case SequenceFileError::CannotWrite: return "cannot be written";
  }
  return "?";
}

/// The first line of the format (its version).
inline constexpr std::string_view kSequenceFileMagic = "safestate-saf-sequence 1";

struct SequenceFileResult {
  SequenceFileError error = SequenceFileError::None;
  int error_number = 0;         // errno for CannotOpen, CannotWrite
  std::uint32_t mode = 0;       // the permission bits, for Permissions
  std::size_t line = 0;         // 1-based, for BadFormat
  std::string_view expected{};  // for BadFormat: what that line must be (static text)
  SequenceState state{};
};

/// Reads `path`: four lines, each ending in a newline --
///   safestate-saf-sequence 1
///   estop <u64 decimal | none>
///   subsystem <u64 decimal | none>
///   service <u64 decimal>
[[nodiscard]] SequenceFileResult load_sequence_file(const char* path) noexcept;

/// Writes `state` to `path` atomically: `path`.tmp (created 0600, O_NOFOLLOW), fsync,
/// rename over `path`, fsync of the folder. No heap; a path longer than 4,000 bytes is
/// CannotWrite (ENAMETOOLONG).
[[nodiscard]] SequenceFileResult store_sequence_file(const char* path, const SequenceState& state) noexcept;

}  // namespace safestate::saf
