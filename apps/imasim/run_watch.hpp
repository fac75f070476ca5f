#pragma once
// `imasim run`'s own figures, step by step (a step observer of the session runner): how far the
// IMA and the chest wall moved, the heart's contacts, the engine's stages and each step's wall
// time for the median, and the progress line.
#include <cstdint>
#include <vector>

#include "physics/step_profile.hpp"
#include "run_progress.hpp"
#include "runner/step_observer.hpp"
#include "scene/thorax_scene.hpp"

namespace imasim::cli {

class RunWatch final : public runner::StepObserver {
 public:
  // `steps`: the run's length, for the step times' room (nothing is allocated while it fits).
  RunWatch(const scene::ThoraxScene& scene, RunProgress& progress, std::uint64_t steps);
  void after_step(const session::SurgicalSession&, const runner::StepRecord& record) override {
    watch(record.result, record.step_ms);
  }
  // After a step of the scene (with or without a session around it).
  void watch(const physics::StepResult& result, double step_ms);

  double median_ms();                                // of the steps' wall times (unit: ms)
  double ima_motion() const { return ima_motion_; }  // (unit: m)
  double chest_wall_motion() const { return chest_wall_motion_; }  // (unit: m)
  std::uint32_t max_contacts() const { return max_contacts_; }
  std::uint64_t missed_heart_contacts() const { return missed_heart_contacts_; }
  const physics::ProfileTotals& profile() const { return profile_; }

 private:
  const scene::ThoraxScene& scene_;
  RunProgress& progress_;
  std::vector<double> step_ms_;
  physics::ProfileTotals profile_;
  double ima_motion_ = 0, chest_wall_motion_ = 0;
  std::uint32_t max_contacts_ = 0;
  std::uint64_t missed_heart_contacts_ = 0;
};

}  // namespace imasim::cli
