// The communications slot of the dispatch order (rank 5, non-critical, §8): the narrow
// interface between the runtime and a communications unit such as ao_modbus_server.
// Every call is non-blocking and allocation-free after start(); start() may allocate
// (e.g. the libmodbus context) because it runs during init, before the first tick.
#pragma once

#include "safestate/pro/comms_requests.hpp"
#include "safestate/pro/process_image.hpp"
#include "safestate/pro/unit_status.hpp"

namespace safestate::pro {

class CommunicationsUnit {
 public:
  CommunicationsUnit() = default;
  CommunicationsUnit(const CommunicationsUnit&) = delete;
  CommunicationsUnit& operator=(const CommunicationsUnit&) = delete;
  virtual ~CommunicationsUnit() = default;

  // Init: acquire resources (bind the socket). READY on success, FAILED otherwise.
  [[nodiscard]] virtual UnitStatus start() noexcept = 0;
  // One dispatch: serve a bounded number of pending requests against `image` and return
  // without waiting for input. Called only while the unit is READY and the supervisor
  // dispatches non-critical units (RUN).
  virtual void on_tick(const ProcessImage& image) noexcept = 0;
  // The requests received since the last call; a request is handed over once.
  [[nodiscard]] virtual CommsRequests take_requests() noexcept = 0;
  // Controlled shutdown step 2: release resources (close the socket, disconnect clients);
  // STOPPED afterwards. Serves nothing after this.
  [[nodiscard]] virtual UnitStatus stop() noexcept = 0;
  [[nodiscard]] virtual UnitStatus status() const noexcept = 0;
};

}  // namespace safestate::pro
