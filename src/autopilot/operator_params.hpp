#pragma once
// The scripted operator's parameters. It is a test operator that performs the
// paper's standard task through the device interface, not a model of surgeons: these knobs vary
// its trials in stated ways, nothing more.
#include <cstdint>

#include "math/types.hpp"

namespace imasim::autopilot {

struct OperatorParams {
  std::uint64_t seed = 1;  // tremor phases and frequencies, the small per-trial variation
  Real speed = 1;          // on every nominal speed (1: the hook cuts at 10 mm/s)
  // Shifts every working line across the vessel: > 0 away from the heart, < 0 towards it
  // (unit: m).
  Real side_bias = 0;
  Real tremor = Real(1e-4);  // RMS of each tool's 8-12 Hz physiological tremor (unit: m)
  // The distance kept from the heart's surface: base + gain x the heart's largest excursion over
  // a beat under the harvested segment (0 for a static heart). The dynamic and static groups
  // of a study differ through this term.
  Real keep_out_base = Real(0.002);  // (unit: m)
  Real keep_out_gain = Real(0.3);    // (unit: m per m of excursion)
  Real segment_length = Real(0.10);  // the harvested length of the IMA (unit: m)
};

}  // namespace imasim::autopilot
