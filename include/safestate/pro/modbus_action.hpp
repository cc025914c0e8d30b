// What ao_modbus_server does with one received frame (docs/design/protection.md,
// "Modbus register map", errors).
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class ModbusAction : std::uint8_t {
  serve,             // a valid request: libmodbus answers it from the register map
  reply_exception,   // answer with the verdict's exception code
  discard,           // drop the frame without a reply; the connection stays open
  close_connection,  // the byte stream cannot be framed any more: disconnect the client
};

}  // namespace safestate::pro
