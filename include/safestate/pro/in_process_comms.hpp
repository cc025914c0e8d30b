// A CommunicationsUnit without a network: the operator panel of the demo and the tests.
// It shows the last image and takes a latch clear request from a local call, through the
// same interface as ao_modbus_server.
#pragma once

#include "safestate/pro/communications_unit.hpp"

namespace safestate::pro {

class InProcessComms final : public CommunicationsUnit {
 public:
  // fail_start: start() reports FAILED (a server that cannot bind its socket).
  explicit InProcessComms(bool fail_start = false) noexcept : fail_start_(fail_start) {}

  [[nodiscard]] UnitStatus start() noexcept override {
    status_ = fail_start_ ? UnitStatus::failed : UnitStatus::ready;
    return status_;
  }
  void on_tick(const ProcessImage& image) noexcept override {
    image_ = image;
    ++served_;
  }
  [[nodiscard]] CommsRequests take_requests() noexcept override {
    const CommsRequests r = pending_;
    pending_ = {};
    return r;
  }
  [[nodiscard]] UnitStatus stop() noexcept override {
    status_ = UnitStatus::stopped;
    return status_;
  }
  [[nodiscard]] UnitStatus status() const noexcept override { return status_; }

  // The operator writes coil 0.
  void request_clear() noexcept { pending_.latch_clear_request = true; }
  void fail() noexcept { status_ = UnitStatus::failed; }
  void recover() noexcept {
    if (status_ == UnitStatus::failed) status_ = UnitStatus::ready;
  }
  [[nodiscard]] const ProcessImage& image() const noexcept { return image_; }
  [[nodiscard]] unsigned served() const noexcept { return served_; }

 private:
  bool fail_start_;
  UnitStatus status_{UnitStatus::init};
  CommsRequests pending_{};
  ProcessImage image_{};
  unsigned served_{0};
};

}  // namespace safestate::pro
