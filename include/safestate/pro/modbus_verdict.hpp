// The request check's verdict on one frame: what to do, the exception code to answer with
// (reply_exception only), why, and whether serving it requests a latch clear (coil 0 := 1).
#pragma once

#include "safestate/pro/modbus_action.hpp"
#include "safestate/pro/modbus_exception.hpp"
#include "safestate/pro/modbus_reason.hpp"

namespace safestate::pro {

struct ModbusVerdict {
  ModbusAction action{ModbusAction::serve};
  ModbusException exception{ModbusException::none};
  ModbusReason reason{ModbusReason::ok};
  bool requests_latch_clear{false};
};

}  // namespace safestate::pro
