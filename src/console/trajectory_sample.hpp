#pragma once
// A session's state as the recorder samples it (metrics/trajectory_recorder.hpp): each
// instrument's tip, orientation, jaw, device pose and clutch, and the force its hand is given
// by eq. 17-19, evaluated on the step's local model with the device where the hand asked (the
// same force the 1 kHz loop renders at the step's instant, before the safety filter).
#include "haptics/force_params.hpp"
#include "metrics/trajectory_recorder.hpp"
#include "session/surgical_session.hpp"

namespace imasim::console {

metrics::TrajectorySample trajectory_sample(const session::SurgicalSession& session,
                                            const haptics::ForceModelParams& forces);

}  // namespace imasim::console
