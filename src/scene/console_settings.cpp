#include "scene/console_settings.hpp"

namespace imasim::scene {

// The values of haptics/force_params.cpp (reasoning in docs/haptics.md); a test keeps the two
// equal.
ConsoleSettings default_console_settings() {
  ConsoleSettings c;
  //        k_d,  c_d, mu,   k_c, cut k_t, cut alpha, coag k_t, coag alpha
  c.force[0] = {4.3, 0.03, 0.2, 5, 0.004, 1000, 0.008, 500};  // fascia
  c.force[1] = {4.3, 0.04, 0.1, 2, 0.002, 1000, 0.008, 500};  // fat
  c.force[2] = {34, 0.34, 0.15, 8, 0.004, 1000, 0.008, 500};  // IMA
  c.force[3] = {400, 3, 0.1, 5, 0.004, 1000, 0.008, 500};     // heart
  c.force[4] = {1000, 5, 0.3, 10, 0.006, 1000, 0.008, 500};   // chest wall
  return c;
}

}  // namespace imasim::scene
