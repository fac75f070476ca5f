#pragma once
// The local model the 1 kHz loop renders between two 5 ms physics steps (SPEC S5):
// per instrument, the contacts of its proxy (point on the surface, normal, tissue kind, the
// surface's velocity) and the cautery's state, published by a physics step at `time_s`. The
// loop evaluates eq. 17-19 against the newest device pose, each contact's plane carried along
// by its surface velocity since the step (so a beating heart's wall keeps moving under the tool
// between steps).
#include <array>
#include <cstdint>

#include "haptics/force_params.hpp"

namespace imasim::haptics {

struct LocalContact {
  Vec3 point = Vec3::Zero();             // on the surface, where the proxy touches (unit: m)
  Vec3 normal = Vec3::UnitZ();           // unit, out of the tissue
  Vec3 surface_velocity = Vec3::Zero();  // of the surface at the point (unit: m/s)
  TissueKind tissue = TissueKind::fascia;
  // The contact point relative to the proxy's reference point: the device's matching point is
  // its reference point plus this (zero when the device's point is given directly).
  Vec3 lever = Vec3::Zero();
};

inline constexpr std::size_t kMaxLocalContacts = 8;

struct LocalModel {
  double time_s = 0;  // simulation time of the step that published it (unit: s)
  std::uint64_t step = 0;
  std::array<LocalContact, kMaxLocalContacts> contacts{};
  std::uint32_t contact_count = 0;
  CauteryMode cautery = CauteryMode::off;
  Real power_w = 0;  // electrosurgical power while active (unit: W)
  // Where a hand pose puts the device in the scene between steps (the arm's motion scaling
  // from its clutch anchors): point = tool_anchor + motion_scale (hand - hand_anchor); a tool
  // pose has scale 1 and zero anchors.
  Vec3 hand_anchor = Vec3::Zero(), tool_anchor = Vec3::Zero();
  Real motion_scale = 1;
};

// The device tip's state in the scene frame (after motion scaling).
struct DeviceTip {
  Vec3 position = Vec3::Zero();  // (unit: m)
  Vec3 velocity = Vec3::Zero();  // (unit: m/s)
};

// The device's reference point (the hinge) and velocity in the scene frame for a hand at
// `hand_position` moving at `hand_velocity` (unit: m, m/s).
DeviceTip device_in_scene(const LocalModel& model, const Vec3& hand_position,
                          const Vec3& hand_velocity);

// The force at time `now_s` (the publisher's clock): eq. 17-19 per contact, with d the depth of
// the device's point (tip.position + the contact's lever) past the contact's plane, summed per
// channel, each channel's sum clamped again to its bound (two contacts do not double eq. 17's
// 5 N).
ForceChannels evaluate_local_model(const LocalModel& model, const ForceModelParams& params,
                                   const DeviceTip& tip, double now_s);

}  // namespace imasim::haptics
