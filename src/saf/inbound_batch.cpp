// SPDX-License-Identifier: Apache-2.0
#include "safestate/saf/inbound_batch.hpp"

#include <algorithm>

namespace safestate::saf {

bool InboundBatch::push(const std::uint8_t* data, std::size_t size, const Source& source, Sender from,
                        bool fresh) noexcept {
  if (count == items.size()) return false;
  sources[count] = source;
  Datagram& d = items[count++];
  d.size = size;
  d.from = from;
  d.fresh = fresh;
  const std::size_t kept = std::min(size, kMaxDatagram);
  if (kept > 0 && data != nullptr) std::copy(data, data + kept, d.bytes.begin());
  return true;
}

}  // namespace safestate::saf
