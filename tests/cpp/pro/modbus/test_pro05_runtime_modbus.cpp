// GoogleTest of ao_modbus_server in the communications slot of the runtime (PRO-02, PRO-05;
// docs/design/protection.md §10a, §10b): a real Modbus TCP client (libmodbus, in its own
// thread) reads the registers the runtime publishes and writes the latch clear request
// (coil 0), which reaches ao_safety through the dispatch cycle: denied while hot, accepted
// when cool; the controlled shutdown stops the server.
#include <gtest/gtest.h>
#include <modbus/modbus.h>

#include <array>
#include <atomic>
#include <chrono>
#include <thread>

#include "safestate/pro/ao_modbus_server.hpp"
#include "safestate/pro/protection_runtime.hpp"
#include "safestate/pro/thermal_plant.hpp"

namespace {

using namespace safestate::pro;  // NOLINT

struct Loop {
  AoModbusServer server{ModbusServerConfig{0, 1, 5, 600}};
  ProtectionRuntime rt{server};
  ThermalPlant plant;
  TickReport tick() {
    const TickReport r = rt.tick(plant.inputs());
    plant.step(r.fan_output, r.load_enable);
    return r;
  }
  ProtectionState prot() const { return rt.safety().context().protection_state; }
};

struct ClientResult {
  int read = -1;
  int write = -1;
  std::array<std::uint16_t, 6> registers{};
};

// One client session (read the six input registers, then optionally write coil 0) while
// the runtime keeps ticking in this thread; the bound on ticks only ends a hung test.
ClientResult session(Loop& l, bool write_clear) {
  ClientResult out;
  std::atomic<bool> done{false};
  const std::uint16_t port = l.server.port();
  std::thread client([&] {
    modbus_t* c = modbus_new_tcp("127.0.0.1", port);
    modbus_set_response_timeout(c, 10, 0);
    if (modbus_connect(c) == 0) {
      out.read = modbus_read_input_registers(c, 0, 6, out.registers.data());
      // The write-enable handshake, then the clear (design page, Modbus register map).
      if (write_clear && modbus_write_bit(c, 1, 1) == 1) out.write = modbus_write_bit(c, 0, 1);
      modbus_close(c);
    }
    modbus_free(c);
    done = true;
  });
  for (int i = 0; i < 20000 && !done; ++i) {
    (void)l.tick();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  client.join();
  return out;
}

TEST(PRO05_RuntimeModbus, AClientReadsTheRuntimesRegistersAndItsClearRequestReachesSafety) {
  Loop l;
  ASSERT_EQ(l.tick().state, SupervisorState::run);  // the server started: every gate passed
  ASSERT_NE(l.server.port(), 0);
  // A blocked air inlet: the hazard persists with the equipment disabled.
  l.plant.set_heat_load_w(600);
  l.plant.set_ambient_c(95);
  for (int i = 0; i < 400 && l.prot() == ProtectionState::normal; ++i) (void)l.tick();
  ASSERT_EQ(l.prot(), ProtectionState::protection);

  // While hot: the registers show the protection, the clear request is denied.
  ClientResult hot = session(l, true);
  ASSERT_EQ(hot.read, 6);
  ASSERT_EQ(hot.write, 1);
  EXPECT_GT(static_cast<std::int16_t>(hot.registers[0]), 85);
  EXPECT_EQ(hot.registers[2], kSafeFanCommandPercent);
  EXPECT_EQ(hot.registers[3], 1U);             // PROTECTION
  EXPECT_EQ(hot.registers[4], 1U);             // RUN
  for (int i = 0; i < 3; ++i) (void)l.tick();  // the request is taken, then consumed
  EXPECT_EQ(l.prot(), ProtectionState::protection);
  EXPECT_EQ(l.rt.data().last_clear, ClearOutcome::denied);

  // Cool: the same request is accepted and regulation resumes.
  l.plant.set_ambient_c(25);
  for (int i = 0; i < 2000 && l.plant.temperature_c() > 60.0; ++i) (void)l.tick();
  ClientResult cool = session(l, true);
  ASSERT_EQ(cool.write, 1);
  EXPECT_EQ(cool.registers[5], 2U);  // the last outcome so far: denied
  for (int i = 0; i < 3; ++i) (void)l.tick();
  EXPECT_EQ(l.prot(), ProtectionState::normal);
  EXPECT_EQ(l.rt.data().last_clear, ClearOutcome::accepted);

  // Controlled shutdown: step 2 stops the server; nothing listens afterwards.
  const std::uint16_t port = l.server.port();
  l.rt.request_shutdown();
  for (int i = 0; i < 20 && l.rt.supervisor().state() != SupervisorState::stopped; ++i) (void)l.tick();
  EXPECT_EQ(l.rt.supervisor().state(), SupervisorState::stopped);
  EXPECT_EQ(l.server.status(), UnitStatus::stopped);
  EXPECT_EQ(l.server.open_connections(), 0U);
  modbus_t* late = modbus_new_tcp("127.0.0.1", port);
  EXPECT_EQ(modbus_connect(late), -1);
  modbus_free(late);
}

}  // namespace
