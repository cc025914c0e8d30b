// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/safety_client_sim.hpp"

#include <array>

namespace safestate::saf {

void SafetyClientSim::step(std::uint16_t service_port) noexcept {
  switch (mode_) {
    case ClientMode::Clear:
    case ClientMode::Emergency:
      last_ = encode_set_estop(mode_ == ClientMode::Emergency, component_id_, sequence_++, key_);
      (void)ep_.send_to(service_port, last_);
      break;
    case ClientMode::Silent: break;
    case ClientMode::Garbage: {
      // A Set Estop header with a corrupted payload, then random bytes of random length.
      Encoded e = encode(Message::set_estop(false));
      e.bytes[kHeaderSize] = 0xA5;
      (void)ep_.send_to(service_port, e);
      std::array<std::uint8_t, 80> junk{};
      for (std::uint8_t& b : junk) {
        garbage_seed_ = garbage_seed_ * 1664525U + 1013904223U;
        b = static_cast<std::uint8_t>(garbage_seed_ >> 24U);
      }
      (void)ep_.send_to(service_port, junk.data(), 1 + (garbage_seed_ % junk.size()));
      break;
    }
  }
}

}  // namespace safestate::saf
