// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/estop_extension.hpp"

namespace safestate::saf {

Encoded encode_set_estop(bool emergency, std::uint32_t client_id, std::uint64_t sequence, const MacKey& key) noexcept {
  Message m = Message::set_estop(emergency);
  m.component_id = client_id;
  m.sequence = sequence;
  m.estop_form = key.present() ? EstopForm::Authenticated : EstopForm::Sequenced;
  Encoded e = encode(m);
  if (key.present()) {
    const Digest d = hmac_sha256(key.bytes.data(), key.size, e.bytes.data(), kEstopMacCovered);
    for (std::size_t i = 0; i < d.size(); ++i) e.bytes[kEstopMacCovered + i] = d[i];
  }
  return e;
}

bool estop_mac_valid(const std::uint8_t* data, std::size_t size, const MacKey& key) noexcept {
  if (!key.present() || data == nullptr || size != kHeaderSize + kEstopAuthenticatedPayload) return false;
  const Digest d = hmac_sha256(key.bytes.data(), key.size, data, kEstopMacCovered);
  return mac_equal(d.data(), data + kEstopMacCovered, d.size());
}

}  // namespace safestate::saf
