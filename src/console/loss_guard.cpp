#include "console/loss_guard.hpp"

namespace imasim::console {

namespace {

// Physics steps that must see a hand held before it may follow its returned device: the step
// that read the input before the hold began may publish after it, so one is not enough.
constexpr std::uint64_t kStepsHeld = 2;

}  // namespace

LossGuard::LossGuard(std::vector<std::array<bool, kParts>> drives)
    : drives_(std::move(drives)), state_(drives_.size(), Link::never) {}

void LossGuard::begin(std::size_t p, std::uint64_t model_step, devices::ConsoleInput& raw) {
  ++parts_[p].losses;
  if (parts_[p].held) return;  // another device of the same part was lost before: still held
  parts_[p].held = true;
  Hold& hold = holds_[p];
  hold.model_step = model_step;
  if (p == std::size_t(Part::pedal)) {
    raw.pedal = haptics::CauteryMode::off;  // the foot must press again
    return;
  }
  const devices::Hand h = devices::Hand(p);
  hold.hand = last_out_.hand(h);
  hold.hand.clutch = true;  // the instrument holds still; the hand is free
  hold.hand.velocity = Vec3::Zero();
  hold.hand.lost = true;
  // The device's claims are void: a returned device is read afresh.
  devices::HandInput& claimed = raw.hand(h);
  claimed.has_pose = false;
  claimed.has_buttons = false;
  claimed.clutch = false;
  claimed.velocity = Vec3::Zero();
}

std::array<bool, 2> LossGuard::apply(double now_s, const std::vector<bool>& connected,
                                     std::uint64_t model_step, devices::ConsoleInput& raw,
                                     devices::ConsoleInput& out) {
  const double dt = now_s > last_s_ ? now_s - last_s_ : 0.0;
  last_s_ = now_s;
  for (PartLoss& part : parts_)
    if (part.held) part.lost_s += dt;  // counted from the tick the loss was seen
  // Losses seen this tick, and which parts still wait for a device that is away.
  std::array<bool, kParts> away{};
  for (std::size_t k = 0; k < drives_.size(); ++k) {
    const bool up = k < connected.size() && connected[k];
    if (state_[k] == Link::up && !up) {
      state_[k] = Link::lost;
      for (std::size_t p = 0; p < kParts; ++p)
        if (drives_[k][p]) begin(p, model_step, raw);
    } else if (up) {
      state_[k] = Link::up;
    }
    if (state_[k] == Link::lost)
      for (std::size_t p = 0; p < kParts; ++p)
        away[p] = away[p] || drives_[k][p];
  }
  // Holds end when their devices are back and, for a hand, it has a new pose that the physics
  // can re-anchor to after seeing the hand held.
  std::array<bool, 2> ended{};
  for (std::size_t p = 0; p < kParts; ++p) {
    if (!parts_[p].held || away[p]) continue;
    const Hold& hold = holds_[p];
    if (model_step != 0 && model_step < hold.model_step + kStepsHeld) continue;
    if (p != std::size_t(Part::pedal)) {
      if (!raw.hand(devices::Hand(p)).has_pose) continue;
      ended[p] = true;
    }
    parts_[p].held = false;
  }

  out = raw;
  bool any_held = false;
  for (std::size_t h = 0; h < 2; ++h) {
    devices::HandInput& hand = out.hand(devices::Hand(h));
    if (parts_[h].held)
      hand = holds_[h].hand;
    else
      hand.lost = false;
    any_held = any_held || parts_[h].held;
  }
  out.pedal_lost = parts_[std::size_t(Part::pedal)].held;
  // A console missing a hand or its pedal delivers no energy until it is whole again.
  if (any_held || out.pedal_lost) {
    out.pedal = haptics::CauteryMode::off;
    out.power_w = 0;
  }
  last_out_ = out;
  return ended;
}

}  // namespace imasim::console
