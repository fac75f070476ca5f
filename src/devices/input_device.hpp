#pragma once
// One interface for every input device: desktop haptic devices and trackers over
// OpenIGTLink, gamepads, 3D mice, scripted playback. A device drives part of the console (one
// hand, both, the pedals): poll() writes what it owns into the ConsoleInput and leaves the rest.
// All calls come from one thread (the 1 kHz loop's) and never block.
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "devices/device_counts.hpp"
#include "devices/hand_input.hpp"

namespace imasim::devices {

struct DeviceInfo {
  std::string kind;     // "openigtlink", "gamepad", "spacemouse", "script", ...
  std::string name;     // what the device calls itself, or its address
  std::string mapping;  // how its inputs reach the console, one line a control
  bool connected = false;
  bool force_feedback = false;
  Real max_force_n = 0;             // the largest force it can render (unit: N)
  Vec3 workspace_m = Vec3::Zero();  // extent of the hand's reach per axis (unit: m)
  bool drives_left = false, drives_right = false, drives_pedal = false;
  // What it refused (a protocol's messages): counts by reason and by the sender's device name,
  // and the peers it has had; empty for devices that refuse nothing.
  std::vector<std::pair<std::string, std::uint64_t>> refused_by_reason, refused_by_name;
  std::uint64_t peers_seen = 0, peers_dropped = 0;
  std::uint64_t peers_timed_out = 0;    // of those dropped: stalled mid-message or idle
  std::uint64_t peers_turned_away = 0;  // closed at once: every slot was taken
  std::uint64_t peers_connected = 0;    // now
  std::uint64_t reconnects = 0;         // a client's calls again that took
  std::uint64_t forces_skipped = 0;     // not sent: the peer's socket was full (it reads no forces)
};

class InputDevice {
 public:
  virtual ~InputDevice() = default;
  // Reads what has arrived and updates the parts of `input` this device drives. `now_s`: the
  // loop's clock (unit: s).
  virtual void poll(double now_s, ConsoleInput& input) = 0;
  // The force to render on one hand (unit: N, scene frame); ignored without force feedback.
  virtual void send_force(Hand hand, const Vec3& force_n, double now_s) = 0;
  // Whether it answers now (cheap: called every tick).
  virtual bool connected() const = 0;
  // Adds what it refused and the peers it served (no allocation: the 1 kHz loop calls it).
  virtual void add_counts(DeviceCounts&) const {}
  // Per part it drives (left hand, right hand, pedal), whether what drives it answers now: a
  // device served by several peers loses a part with the peer that drove it (cheap: every tick).
  virtual std::array<bool, 3> parts_connected() const {
    const bool up = connected();
    return {up, up, up};
  }
  virtual DeviceInfo info() const = 0;  // (allocates: not for every tick)
  // Bit r: refusal reason r (the device's own numbering) seen at least once, and how many it
  // refused in all (cheap: every tick).
  virtual std::uint32_t refusal_reasons() const { return 0; }
  virtual std::uint64_t refused_total() const { return 0; }
  // On the polling thread as it ends: a device whose library keeps thread-local state there
  // (SDL's error strings) frees it.
  virtual void polling_thread_ending() {}
};

}  // namespace imasim::devices
