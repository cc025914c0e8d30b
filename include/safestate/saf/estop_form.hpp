// SPDX-License-Identifier: Apache-2.0
// The three wire forms of Set Estop: the seed's and the two of the documented extension
// (design §14). Encoding with the MAC: estop_extension.hpp.
#pragma once

#include <cstdint>
#include <string_view>

namespace safestate::saf {

enum class EstopForm : std::uint8_t {
  Seed,           // payload 1: u8 emergency (the seed's message)
  Sequenced,      // payload 13: u8 emergency, u32 client component id, u64 sequence
  Authenticated,  // payload 45: as Sequenced, then 32 bytes HMAC-SHA256(key, datagram bytes 0 .. 22)
};

inline constexpr std::uint16_t kEstopSeedPayload = 1;
inline constexpr std::uint16_t kEstopSequencedPayload = 13;
inline constexpr std::uint16_t kEstopAuthenticatedPayload = kEstopSequencedPayload + 32;

[[nodiscard]] constexpr std::string_view to_string(EstopForm f) noexcept {
  switch (f) {
    case EstopForm::Seed: return "SEED";
    case EstopForm::Sequenced: return "SEQUENCED";
    case EstopForm::Authenticated: return "AUTHENTICATED";
  }
  return "?";
}

}  // namespace safestate::saf
