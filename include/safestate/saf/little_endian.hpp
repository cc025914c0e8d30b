// SPDX-License-Identifier: Apache-2.0
// Little-endian field access of the wire format (design §10), shared by the codec and the
// sealed link (§15).
#pragma once

#include <cstddef>
#include <cstdint>

namespace safestate::saf::le {

[[nodiscard]] inline std::uint64_t read_u64(const std::uint8_t* p) noexcept {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8U) | p[i];
  return v;
}
[[nodiscard]] inline std::uint32_t read_u32(const std::uint8_t* p) noexcept {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8U) | p[i];
  return v;
}
[[nodiscard]] inline std::uint16_t read_u16(const std::uint8_t* p) noexcept {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8U));
}
/// The low `n` bytes of `v`, least significant first.
inline void write(std::uint8_t* p, std::uint64_t v, std::size_t n) noexcept {
  for (std::size_t i = 0; i < n; ++i) p[i] = static_cast<std::uint8_t>(v >> (8U * i));
}

}  // namespace safestate::saf::le
