// PRO-05 communications unit: the Modbus register map and its scaling
// (docs/design/protection.md, "Modbus register map").
#include <gtest/gtest.h>

#include <cstdint>

#include "safestate/pro/modbus_register_map.hpp"

namespace {

using namespace safestate::pro;

TEST(PRO05_ModbusRegisterMap, AddressesAreConsecutiveFromZero) {
  for (std::uint16_t i = 0; i < kInputRegisters.size(); ++i) EXPECT_EQ(kInputRegisters[i].address, i);
  EXPECT_EQ(kModbusCoilCount, 2);
  EXPECT_EQ(kLatchClearCoil, 0);
  EXPECT_EQ(kWriteEnableCoil, 1);
  EXPECT_EQ(kModbusDiscreteInputCount, 0);
  EXPECT_EQ(kModbusHoldingRegisterCount, 0);
}

TEST(PRO05_ModbusRegisterMap, EachFieldLandsInItsRegisterUnscaled) {
  ProcessImage image;
  image.temperature_c = 86;
  image.voltage_dv = 179;
  image.fan_command_percent = 100;
  image.protection_state = 1;
  image.supervisor_state = 2;
  image.last_clear_result = 2;
  const auto r = encode_input_registers(image);
  EXPECT_EQ(r[0], 86);   // degC
  EXPECT_EQ(r[1], 179);  // 17.9 V in decivolts
  EXPECT_EQ(r[2], 100);  // percent
  EXPECT_EQ(r[3], 1);    // PROTECTION
  EXPECT_EQ(r[4], 2);    // DEGRADED
  EXPECT_EQ(r[5], 2);    // denied
}

TEST(PRO05_ModbusRegisterMap, NegativeTemperatureIsTwosComplement) {
  ProcessImage image;
  image.temperature_c = -40;
  EXPECT_EQ(encode_input_registers(image)[0], 0xFFD8);
  image.temperature_c = -1;
  EXPECT_EQ(encode_input_registers(image)[0], 0xFFFF);
  image.temperature_c = 150;
  EXPECT_EQ(encode_input_registers(image)[0], 150);
}

TEST(PRO05_ModbusRegisterMap, VoltageBoundsOfTheHazardAreExactInDecivolts) {
  ProcessImage image;
  for (const std::uint16_t dv : {std::uint16_t{180}, std::uint16_t{300}, std::uint16_t{600}}) {
    image.voltage_dv = dv;
    EXPECT_EQ(encode_input_registers(image)[1], dv);
  }
}

TEST(PRO05_ModbusRegisterMap, TheMapIsAConstantExpression) {
  constexpr ProcessImage image{-5, 240, 30, 0, 1, 0, 0};
  constexpr auto r = encode_input_registers(image);
  static_assert(r[0] == 0xFFFB && r[1] == 240 && r[2] == 30 && r[4] == 1);
  EXPECT_EQ(r[2], 30);
}

}  // namespace
