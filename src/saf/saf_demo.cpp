// SPDX-License-Identifier: Apache-2.0
// `safestate demo saf` / build/cpp/src/saf/saf_demo: the Safety service over UDP on the
// loopback interface against a simulated Safety Client and subsystem (Subsystem State
// service with access control, health summary). One line per change. Exits 1 if a
// scenario does not reach its expected outcome within its cycle budget.
//
// Time is virtual by default (cycles run back to back); --realtime sleeps CYCLEINTERVAL.
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string_view>  // to_string() views are literals: .data() is NUL-terminated
#include <thread>

#include "safestate/saf/safety_client_sim.hpp"
#include "safestate/saf/safety_service.hpp"
#include "safestate/saf/subsystem_sim.hpp"

namespace {

using namespace safestate::saf;

class Rig {
 public:
  Rig(UdpEndpoint service_ep, UdpEndpoint client_ep, UdpEndpoint subsystem_ep, bool realtime)
      : ep_(static_cast<UdpEndpoint&&>(service_ep)),
        svc_(Config{}),
        client_(static_cast<UdpEndpoint&&>(client_ep)),
        subsystem_(static_cast<UdpEndpoint&&>(subsystem_ep)),
        realtime_(realtime) {}

  SafetyClientSim& client() { return client_; }
  SubsystemSim& subsystem() { return subsystem_; }
  const SafetyService& service() const { return svc_; }
  void set_hardware_fault(bool on) { hw_ = on; }

  /// One cycle: the peers act, the service reads its socket, cycles, sends its outbox.
  void cycle() {
    client_.step(ep_.port());
    subsystem_.step();
    InboundBatch batch{};
    ep_.receive_batch(batch);
    // The demo's endpoint binds no senders: each datagram counts as from the peer of its kind.
    for (std::size_t i = 0; i < batch.count; ++i) {
      Datagram& d = batch.items[i];
      const DecodeResult m = decode(d.bytes.data(), d.size);
      d.from = m.ok() && m.message.id == MessageId::SetEstop ? Sender::Client : Sender::Subsystem;
    }
    const CycleResult r = svc_.cycle(batch, hw_);
    for (std::size_t i = 0; i < r.outbox.count; ++i) (void)ep_.send_to(subsystem_.port(), encode(r.outbox.messages[i]));
    subsystem_.step();  // the subsystem applies Set Subsystem State in the same cycle
    report(r);
    ++n_;
    if (realtime_) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }

  /// Runs cycles until `done` holds; false after `budget` cycles without it.
  bool until(const char* what, int budget, const std::function<bool()>& done) {
    for (int i = 0; i < budget; ++i) {
      cycle();
      if (done()) return true;
    }
    std::printf("FAILED: %s not reached within %d cycles\n", what, budget);
    return false;
  }

 private:
  void report(const CycleResult& r) {
    const Observable& o = svc_.observe();
    const SubsystemState sub = subsystem_.state();
    const std::uint64_t rejected = svc_.diagnostics().rejected_total();
    if (o.state == last_.state && o.control == last_.control && sub == last_sub_ && rejected == last_rejected_) return;
    std::printf("[cycle %4llu, t=%6.2f s] %-11s", static_cast<unsigned long long>(n_), static_cast<double>(n_) * 0.05,
                to_string(o.state).data());
    if (o.state != last_.state) {
      std::printf(" (from %s, row %s)", to_string(last_.state).data(), r.state_row.data());
    }
    std::printf(" | control %-9s | subsystem %-11s | holder %s", to_string(o.control).data(), to_string(sub).data(),
                subsystem_.holder() == 0                     ? "nobody"
                : subsystem_.holder() == svc_.component_id() ? "safety service (225)"
                                                             : "other component");
    if (rejected != last_rejected_)
      std::printf(" | rejected datagrams %llu", static_cast<unsigned long long>(rejected));
    std::printf("\n");
    last_ = o;
    last_sub_ = sub;
    last_rejected_ = rejected;
  }

  UdpEndpoint ep_;
  SafetyService svc_;
  SafetyClientSim client_;
  SubsystemSim subsystem_;
  bool realtime_;
  bool hw_ = false;
  std::uint64_t n_ = 0;
  Observable last_{};
  SubsystemState last_sub_ = SubsystemState::Operational;
  std::uint64_t last_rejected_ = 0;
};

UdpEndpoint open_or_die(const char* who) {
  UdpEndpoint ep;
  if (ep.open(0) != UdpError::None) {
    std::fprintf(stderr, "saf_demo: cannot open a UDP socket on 127.0.0.1 for the %s: %s\n", who,
                 std::strerror(ep.last_errno()));
    std::exit(2);
  }
  return ep;
}

}  // namespace

int main(int argc, char** argv) {
  bool realtime = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--realtime") == 0) {
      realtime = true;
    } else {
      std::fprintf(stderr, "usage: saf_demo [--realtime]\nsaf_demo: unknown argument '%s'\n", argv[i]);
      return 2;
    }
  }
  Rig rig(open_or_die("service"), open_or_die("Safety Client"), open_or_die("subsystem"), realtime);
  const SafetyService& s = rig.service();
  const auto in = [&s](SafState st, ControlStatus c) {
    return [&s, st, c] { return s.observe().state == st && s.observe().control == c; };
  };
  const auto sub_is = [&rig](SubsystemState st) { return rig.subsystem().state() == st; };
  std::printf(
      "Safety service over UDP on 127.0.0.1 (CYCLEINTERVAL 0.05 s: ESTOPTIMEOUT 2 cycles, "
      "REPORTDATATIMEOUT 40, MESSAGEINTERVAL 10, CHECKINTERVAL 20, AUTHORITYCODE 225)\n");
  bool ok = true;

  std::printf("-- 1. pairing: the Safety Client starts sending Set Estop (clear)\n");
  ok = ok && rig.until("OPERATIONAL", 10, in(SafState::Operational, ControlStatus::Released));

  std::printf("-- 2. the E-stop is pressed: Set Estop with emergency set\n");
  rig.client().set_mode(ClientMode::Emergency);
  ok = ok && rig.until("EMERGENCY with control", 10, [&] {
    return in(SafState::Emergency, ControlStatus::Held)() && sub_is(SubsystemState::Emergency);
  });

  std::printf("-- 3. the E-stop is cleared\n");
  rig.client().set_mode(ClientMode::Clear);
  ok = ok && rig.until("OPERATIONAL, control released", 10, [&] {
    return in(SafState::Operational, ControlStatus::Released)() && sub_is(SubsystemState::Operational) &&
           rig.subsystem().holder() == 0;
  });

  std::printf("-- 4. the Safety Client stops sending (Set Estop timeout)\n");
  rig.client().set_mode(ClientMode::Silent);
  ok = ok && rig.until("EMERGENCY on timeout", 10, [&] {
    return in(SafState::Emergency, ControlStatus::Held)() && sub_is(SubsystemState::Emergency);
  });
  rig.client().set_mode(ClientMode::Clear);
  ok = ok && rig.until("OPERATIONAL again", 10, in(SafState::Operational, ControlStatus::Released));

  std::printf("-- 4b. the Safety Client sends garbage (rejected, counted; the E-stop times out)\n");
  rig.client().set_mode(ClientMode::Garbage);
  ok = ok && rig.until("EMERGENCY on garbage", 10, in(SafState::Emergency, ControlStatus::Held));
  rig.client().set_mode(ClientMode::Clear);
  ok = ok && rig.until("OPERATIONAL again", 10, in(SafState::Operational, ControlStatus::Released));

  std::printf("-- 5. the subsystem's health summary turns Fatal\n");
  rig.subsystem().set_health(Health::Fatal);
  ok = ok && rig.until("EMERGENCY on health Fatal", 25, [&] {
    return in(SafState::Emergency, ControlStatus::Held)() && sub_is(SubsystemState::Emergency);
  });
  std::printf("-- 5b. a component of higher authority (255) takes control during the emergency\n");
  rig.subsystem().take_control(0x00090909, 255);
  ok = ok && rig.until("control refused, retried", 30, in(SafState::Emergency, ControlStatus::Refused));
  rig.subsystem().release_other();
  ok = ok && rig.until("control taken back", 30, in(SafState::Emergency, ControlStatus::Held));
  rig.subsystem().set_health(Health::Normal);
  ok = ok && rig.until("OPERATIONAL again", 25, in(SafState::Operational, ControlStatus::Released));

  std::printf("-- 6. the platform reports a hardware fault\n");
  rig.set_hardware_fault(true);
  ok = ok && rig.until("FAULT with control", 10,
                       [&] { return in(SafState::Fault, ControlStatus::Held)() && sub_is(SubsystemState::Emergency); });
  rig.set_hardware_fault(false);
  for (int i = 0; i < 20; ++i) rig.cycle();
  if (!ok) {
    std::printf("demo: FAILED\n");
    return 1;
  }
  ok = s.observe().state == SafState::Fault;
  std::printf("-- FAULT is absorbing: still %s after 20 clear cycles\n", to_string(s.observe().state).data());
  std::printf(ok ? "demo: all six scenarios reached their expected outcome\n" : "demo: FAILED\n");
  return ok ? 0 : 1;
}
