#include "harvest_core.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "metrics/trainee_metrics.hpp"
#include "surgery/events.hpp"

namespace imasim::python {

std::array<std::string, kObservationSize> observation_names() {
  return {"forceps_tip_x",
          "forceps_tip_y",
          "forceps_tip_z",
          "hook_tip_x",
          "hook_tip_y",
          "hook_tip_z",
          "forceps_force_normal",
          "forceps_force_tangential",
          "forceps_force_thermal",
          "hook_force_normal",
          "hook_force_tangential",
          "hook_force_thermal",
          "forceps_jaw_angle",
          "hook_pedal",
          "heart_phase_sin",
          "heart_phase_cos",
          "pedicle_divided",
          "time_fraction"};
}

HarvestCore::HarvestCore(const SessionOptions& options, double episode_seconds, Real power_w)
    : options_(options), episode_seconds_(episode_seconds), power_w_(power_w) {
  if (!(episode_seconds > 0 && episode_seconds <= 3600))
    throw std::invalid_argument("episode_seconds: more than 0 and at most 3600 s");
  if (!(power_w > 0 && power_w <= 120))
    throw std::invalid_argument("power_w: more than 0 and at most 120 W");
}

HarvestStep HarvestCore::reset(std::optional<std::uint64_t> seed) {
  if (seed) options_.patient_seed = seed;
  session_.reset();  // the old thorax's memory first
  session_.emplace(options_);
  // Both instruments held where they start: their device poses as set up.
  for (int hand = 0; hand < 2; ++hand)
    session_->set_device_pose(hand, session_->session().stations[std::size_t(hand)].device);
  divided_ = 0;
  injuries_ = 0;
  refused_ = false;
  return observe(0);
}

HarvestStep HarvestCore::step(const float* action, std::size_t size) {
  if (!session_) throw std::logic_error("step before reset");
  if (size != kActionSize)
    throw std::invalid_argument("an action has " + std::to_string(kActionSize) + " values, not " +
                                std::to_string(size));
  for (std::size_t k = 0; k < size; ++k)
    if (!std::isfinite(action[k]))
      throw std::invalid_argument("action[" + std::to_string(k) + "] is not finite");
  const double dt = session_->dt();
  const Real travel = kMaxToolSpeed * Real(dt * double(kPhysicsStepsPerAction));  // (unit: m)
  for (int hand = 0; hand < 2; ++hand) {
    const float* a = action + 4 * hand;
    Pose pose = hand == 0 ? session_->commanded().left.pose : session_->commanded().right.pose;
    for (int c = 0; c < 3; ++c)
      pose.translation[c] += travel * Real(std::clamp(a[c], -1.0f, 1.0f));
    session_->set_device_pose(hand, pose);
  }
  session_->set_jaw(0, action[3] > 0   ? surgery::JawCommand::close
                       : action[3] < 0 ? surgery::JawCommand::open
                                       : surgery::JawCommand::hold);
  session_->set_pedal(action[7] > 0.5f    ? surgery::PedalMode::cut
                      : action[7] < -0.5f ? surgery::PedalMode::coag
                                          : surgery::PedalMode::off,
                      power_w_);
  refused_ = !session_->step(kPhysicsStepsPerAction);

  double reward = -kTimePenalty;
  const double divided = session_->pedicle_divided();
  reward += kProgressReward * (divided - divided_);
  divided_ = divided;
  const std::uint64_t injuries = session_->session().events.count(surgery::EventKind::injury);
  reward -= kInjuryPenalty * double(injuries - injuries_);
  injuries_ = injuries;
  return observe(reward);
}

HarvestStep HarvestCore::observe(double reward) {
  HarvestStep out;
  const metrics::TrajectorySample s = session_->sample();
  const session::SurgicalSession& ss = session_->session();
  std::size_t k = 0;
  for (const metrics::ToolSample& t : s.tools)
    for (int c = 0; c < 3; ++c)
      out.observation[k++] = float(t.tip[c]);
  for (const metrics::ToolSample& t : s.tools) {
    out.observation[k++] = float(t.force_normal);
    out.observation[k++] = float(t.force_tangential);
    out.observation[k++] = float(t.force_thermal);
    // As the trainee metrics' excessive force: either hand's normal force (eq. 17).
    out.max_force_n = std::max(out.max_force_n, double(t.force_normal));
  }
  out.observation[k++] = float(s.tools[0].jaw_angle);
  out.observation[k++] = s.pedal == surgery::PedalMode::cut    ? 1.0f
                         : s.pedal == surgery::PedalMode::coag ? -1.0f
                                                               : 0.0f;
  const double phase = 2 * 3.14159265358979323846 * double(ss.scene.heart.phase);
  out.observation[k++] = float(std::sin(phase));
  out.observation[k++] = float(std::cos(phase));
  out.observation[k++] = float(divided_);
  const double time = double(ss.scene.patch.world.state.time);
  out.observation[k++] = float(std::min(1.0, time / episode_seconds_));
  const double excessive = double(metrics::MetricLimits{}.excessive_force);
  out.reward = reward - kForcePenaltyPerN * std::max(0.0, out.max_force_n - excessive);
  out.pedicle_divided = divided_;
  out.ima_injuries = injuries_;
  out.terminated = divided_ >= 1 || injuries_ > 0;
  out.truncated = !out.terminated && (refused_ || time >= episode_seconds_ - 1e-9);
  return out;
}

}  // namespace imasim::python
