#pragma once
// The device side of an OpenIGTLink console, emulated (`imasim device-emulator` and
// haptics-bench): two desktop haptic devices, each hand a mass-spring-damper pulled toward a
// target path and pushed by the force it receives, stepped at 1 kHz; their poses go out as
// TRANSFORM messages (hand or tool frame), buttons and pedal as SENSOR messages, and the forces
// come back as SENSOR messages.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "devices/hand_input.hpp"
#include "devices/igtl_codec.hpp"

namespace imasim::devices {

struct EmulatedHandParams {
  Real mass = Real(0.1);         // the handle and the operator's hand (unit: kg)
  Real stiffness = 200;          // the operator's grip toward the path (unit: N/m)
  Real damping = 4;              // (unit: N s/m)
  Real max_force_n = Real(3.3);  // what the device renders at most (unit: N)
};

// One hand: m a = k (target - x) - c v + F, semi-implicit Euler.
struct EmulatedHand {
  Vec3 x = Vec3::Zero(), v = Vec3::Zero();
  bool placed = false;
  void step(const EmulatedHandParams& p, const Vec3& target, const Vec3& force, Real dt);
};

// What the operator does at one moment, per hand and with the feet.
struct EmulatorTarget {
  std::array<bool, 2> has_pose{false, false};
  std::array<Pose, 2> pose;  // where the operator steers each hand (unit: m)
  std::array<PoseFrame, 2> frame{PoseFrame::hand, PoseFrame::hand};
  std::array<bool, 2> clutch{false, false};
  std::array<Real, 2> jaw{0, 0};  // 0 open .. 1 closed
  haptics::CauteryMode pedal = haptics::CauteryMode::off;
  Real power_w = 40;
};

class EmulatedConsole {
 public:
  // Connects to imasim's OpenIGTLink server (loopback), retrying for `wait_s`; throws
  // std::runtime_error when nobody answers.
  EmulatedConsole(const std::string& address, std::uint16_t port, double wait_s,
                  EmulatedHandParams params = {}, IgtlNames names = {});
  ~EmulatedConsole();
  EmulatedConsole(const EmulatedConsole&) = delete;
  EmulatedConsole& operator=(const EmulatedConsole&) = delete;

  // One 1 ms tick at device time `t_s`: read the forces that arrived, step both hands toward
  // the target, send poses (every tick) and buttons and pedal (every 10th tick and on change).
  // False once the connection is gone.
  bool tick(double t_s, const EmulatorTarget& target);

  const std::array<Vec3, 2>& force() const { return force_; }
  const std::array<EmulatedHand, 2>& hands() const { return hands_; }
  std::uint64_t forces_received() const { return forces_received_; }

 private:
  bool send(const std::vector<std::uint8_t>& m);
  bool read_forces();

  EmulatedHandParams params_;
  IgtlNames names_;
  int fd_ = -1;
  std::array<EmulatedHand, 2> hands_{};
  std::array<Vec3, 2> force_{Vec3::Zero(), Vec3::Zero()};
  std::vector<std::uint8_t> in_;
  std::uint64_t ticks_ = 0, forces_received_ = 0;
  EmulatorTarget last_sent_{};
};

}  // namespace imasim::devices
