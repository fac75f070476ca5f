#pragma once
// The harvest as a task for a policy (the Python module's HarvestEnv, docs/python.md): an action
// moves both instruments' tool poses and works the forceps' jaws and the cautery's pedal, for
// kPhysicsStepsPerAction physics steps; the observation is the instruments' tips and eq. 17-19
// forces, the heart's phase and the pedicle divided so far; the reward pays for dividing the
// pedicle and charges an injury of the IMA, force above the trainee metrics' excessive force
// and time.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "py_session.hpp"

namespace imasim::python {

// Per action: 4 physics steps of 5 ms, a 50 Hz policy.
inline constexpr std::uint64_t kPhysicsStepsPerAction = 4;
// An action's translation at its bound, per second (unit: m/s): a surgeon's brisk motion.
inline constexpr Real kMaxToolSpeed = Real(0.02);
// The reward's terms (docs/python.md).
inline constexpr double kProgressReward = 100;     // the whole pedicle divided
inline constexpr double kInjuryPenalty = 50;       // an IMA injury (and the episode ends)
inline constexpr double kForcePenaltyPerN = 0.05;  // per N above the excessive force, per action
inline constexpr double kTimePenalty = 0.002;      // per action
inline constexpr double kDefaultEpisodeSeconds = 60;

// [forceps dx dy dz jaw, hook dx dy dz pedal], each in [-1, 1]: the translations scaled by
// kMaxToolSpeed; jaw > 0 closes the forceps, < 0 opens them; pedal > 0.5 cuts, < -0.5
// coagulates, otherwise off.
inline constexpr std::size_t kActionSize = 8;
// See observation_names().
inline constexpr std::size_t kObservationSize = 18;
std::array<std::string, kObservationSize> observation_names();

struct HarvestStep {
  std::array<float, kObservationSize> observation{};
  double reward = 0;
  bool terminated = false;  // the pedicle divided, or the IMA injured
  bool truncated = false;   // the episode's time is up, or a step was refused
  double pedicle_divided = 0;
  std::uint64_t ima_injuries = 0;
  double max_force_n = 0;  // the larger of the two eq. 17 normal forces (unit: N)
};

class HarvestCore {
 public:
  HarvestCore(const SessionOptions& options, double episode_seconds, Real power_w);
  // A new session (a new patient when `seed` is given) with both instruments where they start.
  HarvestStep reset(std::optional<std::uint64_t> seed);
  // Throws std::invalid_argument for an action of the wrong size or not finite.
  HarvestStep step(const float* action, std::size_t size);
  PySession& session() { return *session_; }

 private:
  HarvestStep observe(double reward_so_far);

  SessionOptions options_;
  double episode_seconds_;
  Real power_w_;
  std::optional<PySession> session_;
  double divided_ = 0;
  std::uint64_t injuries_ = 0;
  bool refused_ = false;
};

}  // namespace imasim::python
