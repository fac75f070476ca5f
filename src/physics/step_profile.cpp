#include "physics/step_profile.hpp"

namespace imasim::physics {

const char* to_string(Stage stage) {
  switch (stage) {
    case Stage::instruments:
      return "instruments";
    case Stage::cutting:
      return "cutting";
    case Stage::heart:
      return "heart";
    case Stage::contacts:
      return "contacts";
    case Stage::predict:
      return "predict";
    case Stage::solve:
      return "solve";
    case Stage::velocities:
      return "velocities";
    case Stage::coupling:
      return "coupling";
    case Stage::surfaces:
      return "surfaces";
    case Stage::count:
      break;
  }
  return "unknown";
}

}  // namespace imasim::physics
