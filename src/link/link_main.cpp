// SPDX-License-Identifier: Apache-2.0
// safestate_link: the simulated cell, the SystemStateManager (control thread, 1 ms cycle)
// and the operator link's bridge (WebSocket/HTTP on 127.0.0.1), design §11.
//
//   safestate_link --token-file FILE [--port N] [--www DIR] [--cycle-us N]
//
// Prints "safestate link: http://127.0.0.1:PORT/" on the first line of stdout once it
// listens; stops on SIGINT/SIGTERM. Bad arguments: one line on stderr, exit 2.
#include <pthread.h>
#include <sched.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <thread>

#include "safestate/link/bridge.hpp"
#include "safestate/link/control_loop.hpp"
#include "safestate/link/thread_placement.hpp"

namespace {

[[noreturn]] void usage_error(const std::string& what) {
  std::fprintf(stderr, "safestate_link: %s\n", what.c_str());
  std::exit(2);
}

unsigned long number(std::string_view flag, const char* text, unsigned long max) {
  char* end = nullptr;
  const unsigned long v = std::strtoul(text, &end, 10);
  if (end == text || *end != '\0' || v > max) {
    usage_error(std::string(flag) + ": expected an integer 0.." + std::to_string(max) + ", got '" + text + "'");
  }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace safestate::link;  // NOLINT
  BridgeOptions opts;
  std::string token_file;
  unsigned long cycle_us = 1000;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    const auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage_error(std::string(a) + ": expected a value");
      return argv[++i];
    };
    if (a == "--token-file") token_file = value();
    else if (a == "--port") opts.port = static_cast<unsigned short>(number(a, value(), 65535));
    else if (a == "--www") opts.www = value();
    else if (a == "--cycle-us") cycle_us = number(a, value(), 1000000);
    else usage_error("unknown argument '" + std::string(a) + "' (expected --token-file, --port, --www, --cycle-us)");
  }
  if (token_file.empty()) usage_error("--token-file FILE is required (a file of mode 0600 holding the control token)");
  std::string error;
  if (!read_token_file(token_file, opts.token, error)) usage_error(error);
  if (cycle_us == 0) usage_error("--cycle-us: expected a positive cycle time");

  // SIGINT/SIGTERM go to the signal thread only.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  static ControlLoop loop;  // large (histogram): not on the stack
  std::atomic<bool> stop{false};
  try {
    Bridge bridge(loop, opts);
    std::thread control([&] {
      (void)make_current_thread_realtime();  // best effort (needs privileges)
      loop.run(stop, std::chrono::microseconds(cycle_us));
    });
    std::thread waiter([&] {
      int sig = 0;
      sigwait(&signals, &sig);
      stop.store(true);
      bridge.stop();
    });
    std::printf("safestate link: http://127.0.0.1:%u/\n", static_cast<unsigned>(bridge.port()));
    std::fflush(stdout);
    bridge.run();
    stop.store(true);
    control.join();
    pthread_kill(waiter.native_handle(), SIGTERM);
    waiter.join();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "safestate_link: %s\n", e.what());
    return 2;
  }
  return 0;
}
