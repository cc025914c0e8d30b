// The reason code of posting an event to an active object's queue (§1): a full queue
// rejects the post (and counts it); posting never blocks and never drops silently.
#pragma once

#include <cstdint>

namespace safestate::pro {

// stopped: the receiving AO has stopped (shutdown) and takes no more events.
enum class PostResult : std::uint8_t { ok = 0, queue_full, stopped };

}  // namespace safestate::pro
