// SPDX-License-Identifier: Apache-2.0
// Inputs of one scan cycle (design §2).
#pragma once

#include "safestate/channel_pair.hpp"
#include "safestate/drive_bus_image.hpp"
#include "safestate/enable_position.hpp"
#include "safestate/joint_vector.hpp"
#include "safestate/selector_contacts.hpp"

namespace safestate {

/// Raw electrical levels of one cycle. A value-initialised record (`ScanInputs{}`) is the
/// safe, tripped reading: E-stop pressed, gate open, enabling released, selector invalid,
/// self-test failed, drives not ready, fieldbus lost (WKC 0), robot at rest. A broken wire reads as a demand.
struct ScanInputs {
  ChannelPair<bool> estop_closed;        ///< NC contact closed = released, healthy
  ChannelPair<bool> safeguard_closed;    ///< gate locked / light curtain clear
  ChannelPair<EnablePosition> enabling;  ///< three-position enabling device
  SelectorContacts selector;             ///< AUTO / T1 / T2 contacts
  bool self_test_ok{false};              ///< platform self-test passed (read in BOOT)
  /// Drive status words, bus cycle counter and working counter: servo_ready, drive_fault
  /// and fieldbus_ok (C24) are derived from them in the core (design §2).
  DriveBusImage bus;
  bool operator_link_ok{false};  ///< operator link heartbeat within its period (C26)
  /// C30 (issue 29 item 10): the contactor's auxiliary (mirror) contact reports the main
  /// contacts closed; the brakes' feedback reports them released. Each is compared with the
  /// output the previous cycle wrote (FeedbackMonitor).
  bool contactor_feedback_closed{false};
  bool brake_feedback_released{false};
  JointVector q{};   ///< joint positions, rad
  JointVector qd{};  ///< joint velocities, rad/s
};

}  // namespace safestate
