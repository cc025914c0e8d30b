// The communications slot (rank 5, non-critical, §8) as an active object: it drives a
// CommunicationsUnit (ao_modbus_server, or InProcessComms) once per dispatch with the
// image diagnostics published this tick, and hands the requests to monitoring's next
// snapshot. start/stop are the unit's start()/stop().
#pragma once

#include "safestate/pro/active_object.hpp"
#include "safestate/pro/communications_unit.hpp"
#include "safestate/pro/cycle_data.hpp"

namespace safestate::pro {

class CommsAo final : public ActiveObject {
 public:
  CommsAo(CycleData& data, CommunicationsUnit& unit) noexcept : ActiveObject(AoId::comms), data_(data), unit_(unit) {}
  // The unit's own report (a server whose socket failed reports FAILED by itself).
  void sync_status() noexcept;

 protected:
  void on_event(const AoEvent& e) noexcept override;

 private:
  CycleData& data_;
  CommunicationsUnit& unit_;
};

}  // namespace safestate::pro
