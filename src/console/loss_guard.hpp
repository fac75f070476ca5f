#pragma once
// What a lost device leaves behind: the parts of the console it drove
// (a hand, the pedal) are released at the tick its loss is seen, whatever it last commanded:
//   hand:  the clutch engages (the instrument holds still while the hand is gone), velocity 0;
//   pedal: off, the generator's power 0 (no energy reaches the electrode).
// The device's own last claims (pose, buttons, pedal) are voided, so a device that comes back
// is read afresh: a hand is held until the returned device has sent a new pose and the physics
// has stepped twice with the hand held (it saw the clutch: the arm re-anchors at the new pose
// instead of jumping to it), the pedal stays off until the foot presses it again.
// The force on a lost hand is zeroed by its ForceSafety (device_ok false) at the same tick.
// No allocation after construction: it runs in the 1 kHz loop.
#include <array>
#include <cstdint>
#include <vector>

#include "devices/hand_input.hpp"

namespace imasim::console {

// The console's parts a device can drive.
enum class Part : std::uint8_t { left, right, pedal };
inline constexpr std::size_t kParts = 3;

struct PartLoss {
  std::uint64_t losses = 0;  // times a device driving it was lost
  double lost_s = 0;         // time it was held for a lost device, all losses (unit: s)
  bool held = false;         // held now
};

class LossGuard {
 public:
  // Per device, the parts it drives (left, right, pedal).
  explicit LossGuard(std::vector<std::array<bool, kParts>> drives);

  // After the devices' poll of one tick: `connected[k]` for each device, `model_step` the newest
  // physics step the loop has seen (0: none yet). Voids what lost devices claimed in `raw` (the
  // devices' own input) and writes the input the physics and the forces may use into `out`.
  // Returns, per hand, whether its hold ended this tick (its tremor filter starts anew).
  std::array<bool, 2> apply(double now_s, const std::vector<bool>& connected,
                            std::uint64_t model_step, devices::ConsoleInput& raw,
                            devices::ConsoleInput& out);

  const std::array<PartLoss, kParts>& parts() const { return parts_; }

 private:
  enum class Link : std::uint8_t { never, up, lost };  // a device never seen is not lost
  struct Hold {
    std::uint64_t model_step = 0;  // the newest physics step when the hold began
    devices::HandInput hand;       // what the physics is given while held
  };
  void begin(std::size_t part, std::uint64_t model_step, devices::ConsoleInput& raw);

  std::vector<std::array<bool, kParts>> drives_;
  std::vector<Link> state_;
  std::array<PartLoss, kParts> parts_{};
  std::array<Hold, kParts> holds_{};
  devices::ConsoleInput last_out_{};
  double last_s_ = 0;
};

}  // namespace imasim::console
