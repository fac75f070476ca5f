#include "run_watch.hpp"

#include <algorithm>

#include "report.hpp"
#include "tissue/mesh_object.hpp"

namespace imasim::cli {

RunWatch::RunWatch(const scene::ThoraxScene& scene, RunProgress& progress, std::uint64_t steps)
    : scene_(scene), progress_(progress) {
  step_ms_.reserve(steps);
}

void RunWatch::watch(const physics::StepResult& result, double step_ms) {
  step_ms_.push_back(step_ms);
  profile_.add(result.profile);
  const tissue::TissueWorld& w = scene_.patch.world;
  max_contacts_ = std::max(max_contacts_, scene_.heart.last_contacts);
  missed_heart_contacts_ += scene_.missed_heart_contacts;
  const tissue::MeshObject& ima = w.meshes[scene_.patch.ima];
  for (std::uint32_t k = 0; k < ima.particle_count; ++k) {
    const std::uint32_t i = ima.first_particle + k;
    ima_motion_ = std::max(
        ima_motion_,
        double((w.state.particles.position[i] - w.state.particles.rest_position[i]).norm()));
  }
  chest_wall_motion_ =
      std::max(chest_wall_motion_, tissue::max_displacement(w, w.meshes[scene_.patch.wall]));
  progress_.update(w.state.time);
}

double RunWatch::median_ms() {
  return median(step_ms_);
}

}  // namespace imasim::cli
