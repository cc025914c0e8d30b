// PRO-05 communications unit: every frame's verdict (serve, exception code, discard, close)
// as docs/design/protection.md "Modbus register map" lists it.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "modbus_test_frames.hpp"
#include "safestate/pro/modbus_request_check.hpp"

namespace {

using namespace safestate::pro;
using modbus_test::frame;

constexpr std::uint8_t kUnit = 1;

ModbusVerdict check(const std::vector<std::uint8_t>& f) { return check_modbus_request(f.data(), f.size(), kUnit); }

void expect_exception(const std::vector<std::uint8_t>& f, ModbusException code, ModbusReason reason) {
  const ModbusVerdict v = check(f);
  EXPECT_EQ(v.action, ModbusAction::reply_exception);
  EXPECT_EQ(v.exception, code);
  EXPECT_EQ(v.reason, reason);
  EXPECT_FALSE(v.requests_latch_clear);
}

TEST(PRO05_ModbusRequestCheck, ValidReadsAndWritesAreServed) {
  for (const auto& f :
       {frame(kUnit, {0x04, 0, 0, 0, 6}), frame(kUnit, {0x04, 0, 5, 0, 1}), frame(kUnit, {0x01, 0, 0, 0, 1}),
        frame(kUnit, {0x05, 0, 0, 0x00, 0x00}), frame(0xFF, {0x04, 0, 0, 0, 1}), frame(0, {0x04, 0, 0, 0, 1})}) {
    const ModbusVerdict v = check(f);
    EXPECT_EQ(v.action, ModbusAction::serve);
    EXPECT_EQ(v.reason, ModbusReason::ok);
    EXPECT_FALSE(v.requests_latch_clear);
  }
}

TEST(PRO05_ModbusRequestCheck, WritingOneToCoilZeroRequestsALatchClear) {
  EXPECT_TRUE(check(frame(kUnit, {0x05, 0, 0, 0xFF, 0x00})).requests_latch_clear);
  EXPECT_TRUE(check(frame(kUnit, {0x0F, 0, 0, 0, 1, 1, 0x01})).requests_latch_clear);
  EXPECT_FALSE(check(frame(kUnit, {0x0F, 0, 0, 0, 1, 1, 0x00})).requests_latch_clear);
  EXPECT_FALSE(check(frame(kUnit, {0x05, 0, 0, 0x00, 0x00})).requests_latch_clear);
  EXPECT_FALSE(check(frame(kUnit, {0x05, 0, 1, 0xFF, 0x00})).requests_latch_clear);  // the write enable
  EXPECT_FALSE(check(frame(kUnit, {0x0F, 0, 1, 0, 1, 1, 0x01})).requests_latch_clear);
}

TEST(PRO05_ModbusRequestCheck, UnsupportedFunctionsAreIllegalFunction) {
  for (const std::uint8_t fc : {0x00, 0x07, 0x08, 0x11, 0x16, 0x17, 0x2B, 0x7F}) {
    expect_exception(frame(kUnit, {fc, 0, 0, 0, 1}), ModbusException::illegal_function,
                     ModbusReason::unsupported_function);
  }
  expect_exception(frame(kUnit, {0x2B}), ModbusException::illegal_function, ModbusReason::unsupported_function);
}

TEST(PRO05_ModbusRequestCheck, AddressesOutsideATableAreIllegalDataAddress) {
  constexpr auto code = ModbusException::illegal_data_address;
  constexpr auto reason = ModbusReason::address_out_of_range;
  expect_exception(frame(kUnit, {0x04, 0, 6, 0, 1}), code, reason);        // past register 5
  expect_exception(frame(kUnit, {0x04, 0, 1, 0, 6}), code, reason);        // 1..6 crosses the end
  expect_exception(frame(kUnit, {0x04, 0xFF, 0xFF, 0, 1}), code, reason);  // no 16-bit wrap
  expect_exception(frame(kUnit, {0x01, 0, 2, 0, 1}), code, reason);        // coil 2
  expect_exception(frame(kUnit, {0x01, 0, 0, 0, 3}), code, reason);        // coils 0..2
  expect_exception(frame(kUnit, {0x05, 0, 2, 0xFF, 0}), code, reason);     // write coil 2
  expect_exception(frame(kUnit, {0x02, 0, 0, 0, 1}), code, reason);        // no discrete inputs
  expect_exception(frame(kUnit, {0x03, 0, 0, 0, 1}), code, reason);        // no holding registers
}

TEST(PRO05_ModbusRequestCheck, WritesToTheReadOnlyRegistersAreIllegalDataAddress) {
  // No function writes input registers; the register writes address the (empty) holding table.
  expect_exception(frame(kUnit, {0x06, 0, 0, 0, 42}), ModbusException::illegal_data_address,
                   ModbusReason::address_out_of_range);
  expect_exception(frame(kUnit, {0x10, 0, 0, 0, 1, 2, 0, 42}), ModbusException::illegal_data_address,
                   ModbusReason::address_out_of_range);
}

TEST(PRO05_ModbusRequestCheck, BadQuantitiesValuesAndLengthsAreIllegalDataValue) {
  constexpr auto code = ModbusException::illegal_data_value;
  expect_exception(frame(kUnit, {0x04, 0, 0, 0, 0}), code, ModbusReason::bad_quantity);
  expect_exception(frame(kUnit, {0x04, 0, 0, 0, 126}), code, ModbusReason::bad_quantity);
  expect_exception(frame(kUnit, {0x01, 0, 0, 0, 0}), code, ModbusReason::bad_quantity);
  expect_exception(frame(kUnit, {0x01, 0, 0, 0x07, 0xD1}), code, ModbusReason::bad_quantity);  // 2001
  expect_exception(frame(kUnit, {0x05, 0, 0, 0x12, 0x34}), code, ModbusReason::bad_coil_value);
  expect_exception(frame(kUnit, {0x05, 0, 0, 0x00, 0x01}), code, ModbusReason::bad_coil_value);
  expect_exception(frame(kUnit, {0x0F, 0, 0, 0, 1, 2, 1, 0}), code, ModbusReason::bad_byte_count);
  expect_exception(frame(kUnit, {0x0F, 0, 0, 0, 0, 0}), code, ModbusReason::bad_quantity);
  expect_exception(frame(kUnit, {0x10, 0, 0, 0, 1, 1, 0}), code, ModbusReason::bad_byte_count);
  expect_exception(frame(kUnit, {0x04, 0, 0}), code, ModbusReason::length_mismatch);           // short PDU
  expect_exception(frame(kUnit, {0x04, 0, 0, 0, 1, 0}), code, ModbusReason::length_mismatch);  // long PDU
  expect_exception(frame(kUnit, {0x0F, 0, 0, 0, 1, 1}), code, ModbusReason::length_mismatch);  // values missing
  expect_exception(frame(kUnit, {0x0F, 0, 0}), code, ModbusReason::length_mismatch);
}

TEST(PRO05_ModbusRequestCheck, OtherUnitIdsAndProtocolIdsAreDiscardedWithoutReply) {
  const ModbusVerdict unit = check(frame(7, {0x04, 0, 0, 0, 1}));
  EXPECT_EQ(unit.action, ModbusAction::discard);
  EXPECT_EQ(unit.reason, ModbusReason::wrong_unit_id);
  const ModbusVerdict protocol = check(frame(kUnit, {0x04, 0, 0, 0, 1}, 1));
  EXPECT_EQ(protocol.action, ModbusAction::discard);
  EXPECT_EQ(protocol.reason, ModbusReason::wrong_protocol_id);
}

TEST(PRO05_ModbusRequestCheck, FunctionCodesOfExceptionResponsesAreDiscarded) {
  // 0x84 + 0x80 would wrap to 0x04: an "exception" that reads as a normal response.
  for (const std::uint8_t fc : {0x80, 0x84, 0xFF}) {
    const ModbusVerdict v = check(frame(kUnit, {fc, 0, 0, 0, 1}));
    EXPECT_EQ(v.action, ModbusAction::discard);
    EXPECT_EQ(v.reason, ModbusReason::reserved_function);
  }
}

TEST(PRO05_ModbusRequestCheck, TheMbapLengthFramesTwoTo254Bytes) {
  EXPECT_FALSE(mbap_length_valid(0));
  EXPECT_FALSE(mbap_length_valid(1));
  EXPECT_TRUE(mbap_length_valid(2));
  EXPECT_TRUE(mbap_length_valid(254));
  EXPECT_FALSE(mbap_length_valid(255));
  EXPECT_EQ(kModbusMaxAduSize, 260U);
}

}  // namespace
