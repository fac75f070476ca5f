#pragma once
// How far a harvest got (whether the operator finishes the task), read from the session after the
// run, by the scorer, not by the operator: the pedicle is free when the fat strands that hold the
// harvested segment of the IMA to the chest wall are divided, the fascia over it is open, and
// the vessel is uninjured.
#include <cstdint>

#include "autopilot/harvest_plan.hpp"
#include "session/surgical_session.hpp"

namespace imasim::autopilot {

struct HarvestOutcome {
  std::uint32_t pedicle_strands = 0;          // the IMA's strands along the segment
  std::uint32_t pedicle_strands_divided = 0;  // of those, cut
  std::uint64_t fascia_edges_cut = 0;
  std::uint32_t ima_injuries = 0;  // injury events
  Real divided_share() const {
    return pedicle_strands ? Real(pedicle_strands_divided) / Real(pedicle_strands) : Real(0);
  }
};

// The share of the pedicle's strands that must be divided for the task to count as finished.
inline constexpr Real kPedicleFreeShare = Real(0.9);

HarvestOutcome harvest_outcome(const session::SurgicalSession& session, const HarvestPlan& plan);

// Finished: the pedicle's strands divided (at least kPedicleFreeShare), the fascia cut, and the
// IMA uninjured.
bool harvest_finished(const HarvestOutcome& outcome);

}  // namespace imasim::autopilot
