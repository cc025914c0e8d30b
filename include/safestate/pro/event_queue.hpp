// An active object's bounded event queue (§1): a fixed array (safestate::SpscQueue, no
// heap), FIFO, with a reason code on every post and a count of the posts a full queue
// rejected, so an overflow is reported, never silently lost.
#pragma once

#include <cstddef>
#include <cstdint>

#include "safestate/pro/post_result.hpp"
#include "safestate/spsc_queue.hpp"

namespace safestate::pro {

template <typename E, std::size_t Capacity>
class EventQueue {
 public:
  static constexpr std::size_t kCapacity = Capacity;

  [[nodiscard]] PostResult post(const E& e) noexcept {
    if (queue_.try_push(e)) return PostResult::ok;
    ++overflows_;
    return PostResult::queue_full;
  }
  // The oldest event; false when the queue is empty.
  [[nodiscard]] bool take(E& out) noexcept { return queue_.try_pop(out); }
  [[nodiscard]] std::size_t size() const noexcept { return queue_.size(); }
  [[nodiscard]] std::uint32_t overflow_count() const noexcept { return overflows_; }

 private:
  SpscQueue<E, Capacity> queue_;
  std::uint32_t overflows_{0};
};

}  // namespace safestate::pro
