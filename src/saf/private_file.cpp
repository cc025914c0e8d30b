// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/private_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

namespace safestate::saf {
namespace {

/// One read that retries when a signal interrupts it; -1 with errno set on failure.
ssize_t read_some(int fd, char* data, std::size_t size) noexcept {
  for (;;) {
    const ssize_t n = ::read(fd, data, size);
    if (n >= 0 || errno != EINTR) return n;
  }
}

PrivateFileRead fail(int fd, PrivateFileStatus status, int error_number, std::uint32_t mode) noexcept {
  ::close(fd);
  PrivateFileRead r{};
  r.status = status;
  r.error_number = error_number;
  r.mode = mode;
  return r;
}

}  // namespace

PrivateFileRead read_private_file(const char* path, char* buffer, std::size_t capacity) noexcept {
  PrivateFileRead r{};
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    r.status = errno == ENOENT ? PrivateFileStatus::Missing : PrivateFileStatus::CannotOpen;
    r.error_number = errno;
    return r;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) return fail(fd, PrivateFileStatus::CannotOpen, errno, 0);
  const auto mode = static_cast<std::uint32_t>(st.st_mode & 07777U);
  if (!S_ISREG(st.st_mode)) return fail(fd, PrivateFileStatus::NotRegular, 0, mode);
  if ((st.st_mode & 077U) != 0) return fail(fd, PrivateFileStatus::Permissions, 0, mode);
  std::size_t size = 0;
  for (;;) {
    char extra = 0;
    char* into = size < capacity ? buffer + size : &extra;
    const ssize_t n = read_some(fd, into, size < capacity ? capacity - size : 1);
    if (n < 0) return fail(fd, PrivateFileStatus::CannotOpen, errno, mode);
    if (n == 0) break;
    if (size >= capacity) return fail(fd, PrivateFileStatus::TooLong, 0, mode);
    size += static_cast<std::size_t>(n);
  }
  ::close(fd);
  r.mode = mode;
  r.size = size;
  return r;
}

}  // namespace safestate::saf
