// The Modbus exception codes ao_modbus_server answers with (Modbus Application Protocol
// v1.1b3 §7); the values are the codes on the wire.
#pragma once

#include <cstdint>

namespace safestate::pro {

enum class ModbusException : std::uint8_t {
  none = 0,
  // the function code is not one this server implements, or - the specification's "server
  // in the wrong state to process a request of this type" - a write not authorised now
  illegal_function = 0x01,
  illegal_data_address = 0x02,  // the address (range) is not in the addressed table
  illegal_data_value = 0x03,    // bad quantity, byte count, coil value or PDU length
};

}  // namespace safestate::pro
