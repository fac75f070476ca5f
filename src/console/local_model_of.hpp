#pragma once
// What a physics step tells the 1 kHz loop about one instrument (SPEC S5; haptics/local_model):
// the proxy's coupling to the tissue it presses (one contact along the tissue's force on the
// tool, at the proxy's hinge, so eq. 17's d is the device's depth past the proxy), the heart or
// the chest wall where they stop the proxy, the cautery's mode and power, and the arm's mapping
// from the hand to the scene (motion scaling from the clutch anchors).
#include <cstdint>

#include "haptics/local_model.hpp"
#include "session/surgical_session.hpp"

namespace imasim::console {

haptics::TissueKind tissue_kind(surgery::Tissue tissue);

// `time_s`: the clock the haptic loop reads (the model's age is measured on it).
haptics::LocalModel local_model_of(const session::SurgicalSession& session, int station,
                                   double time_s, std::uint64_t step);

}  // namespace imasim::console
