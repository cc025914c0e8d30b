// The active-object base of the fan controller's units (§1, in the spirit of QP): a
// bounded event queue and a run-to-completion dispatch that handles one event at a time,
// each to its end, before the next. The unit's status is its readiness gate (§6).
#pragma once

#include <cstddef>
#include <cstdint>

#include "safestate/pro/ao_event.hpp"
#include "safestate/pro/ao_id.hpp"
#include "safestate/pro/event_queue.hpp"
#include "safestate/pro/post_result.hpp"
#include "safestate/pro/unit_status.hpp"

namespace safestate::pro {

class ActiveObject {
 public:
  // A tick carries at most: the tick, a status, a fault event and two lifecycle events.
  static constexpr std::size_t kQueueCapacity = 8;

  explicit ActiveObject(AoId id) noexcept : id_(id) {}
  ActiveObject(const ActiveObject&) = delete;
  ActiveObject& operator=(const ActiveObject&) = delete;
  virtual ~ActiveObject() = default;

  [[nodiscard]] PostResult post(const AoEvent& e) noexcept {
    if (status_ == UnitStatus::stopped) return PostResult::stopped;
    return queue_.post(e);
  }

  // Dispatches every queued event, one at a time, each to completion; returns how many.
  std::size_t run_to_completion() noexcept {
    std::size_t n = 0;
    AoEvent e;
    while (queue_.take(e)) {
      on_event(e);
      ++n;
    }
    return n;
  }

  [[nodiscard]] AoId id() const noexcept { return id_; }
  [[nodiscard]] UnitStatus status() const noexcept { return status_; }
  [[nodiscard]] std::uint32_t overflow_count() const noexcept { return queue_.overflow_count(); }
  [[nodiscard]] std::size_t queued() const noexcept { return queue_.size(); }

 protected:
  virtual void on_event(const AoEvent& e) noexcept = 0;
  void set_status(UnitStatus s) noexcept { status_ = s; }
  // start (INIT -> READY) and stop (-> STOPPED), alike for every unit; true when `e` was one.
  bool handle_start_stop(const AoEvent& e) noexcept {
    if (e.signal == AoSignal::start) {
      if (status_ == UnitStatus::init) status_ = UnitStatus::ready;
      return true;
    }
    if (e.signal == AoSignal::stop) {
      status_ = UnitStatus::stopped;
      return true;
    }
    return false;
  }

 private:
  AoId id_;
  UnitStatus status_{UnitStatus::init};
  EventQueue<AoEvent, kQueueCapacity> queue_;
};

}  // namespace safestate::pro
