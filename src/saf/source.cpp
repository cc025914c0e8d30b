// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/source.hpp"

#include <cstdio>
#include <cstring>

namespace safestate::saf {

std::optional<std::uint32_t> parse_ipv4(std::string_view text) noexcept {
  std::uint32_t address = 0;
  std::size_t i = 0;
  for (int part = 0; part < 4; ++part) {
    if (part > 0) {
      if (i >= text.size() || text[i] != '.') return std::nullopt;
      ++i;
    }
    std::uint32_t value = 0;
    std::size_t digits = 0;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9' && digits < 4) {
      value = value * 10U + static_cast<std::uint32_t>(text[i] - '0');
      ++i;
      ++digits;
    }
    if (digits == 0 || digits > 3 || value > 255) return std::nullopt;
    address = (address << 8U) | value;
  }
  if (i != text.size()) return std::nullopt;
  return address;
}

std::string_view PeerText::view() const noexcept { return {chars.data(), std::strlen(chars.data())}; }

PeerText to_text(const Peer& p) noexcept {
  PeerText t{};
  std::snprintf(t.chars.data(), t.chars.size(), "%u.%u.%u.%u:%u", (p.address >> 24U) & 0xFFU,
                (p.address >> 16U) & 0xFFU, (p.address >> 8U) & 0xFFU, p.address & 0xFFU,
                static_cast<unsigned>(p.port));
  return t;
}

}  // namespace safestate::saf
