#include "console/local_model_of.hpp"

namespace imasim::console {

haptics::TissueKind tissue_kind(surgery::Tissue t) {
  switch (t) {
    case surgery::Tissue::fat:
      return haptics::TissueKind::fat;
    case surgery::Tissue::ima:
      return haptics::TissueKind::ima;
    case surgery::Tissue::heart:
      return haptics::TissueKind::heart;
    case surgery::Tissue::chest_wall:
      return haptics::TissueKind::chest_wall;
    case surgery::Tissue::fascia:
    case surgery::Tissue::none:
      break;
  }
  return haptics::TissueKind::fascia;
}

haptics::LocalModel local_model_of(const session::SurgicalSession& s, int station, double time_s,
                                   std::uint64_t step) {
  const session::Station& st = s.stations[std::size_t(station)];
  haptics::LocalModel m;
  m.time_s = time_s;
  m.step = step;
  const Vec3 reference = st.state.controller.translation;  // the proxy's hinge
  // The spring k o carries every force on the proxy: the tissue's and, when the heart or the wall
  // stopped it, theirs. The tissue's plane is put at the depth its share of that force explains at
  // its k_d, so the hand feels what the tissue pushes, whatever the coupling's k (its share
  // rendered at k_d / k of the offset would have been felt k_d / k times).
  const Vec3& offset = st.proxy.offset;
  const Real k = st.proxy.coupling;
  const Vec3 spring = k * offset;
  const bool stopped = st.stop.tissue != surgery::Tissue::none;
  const Real pushed = st.proxy.normal_force.norm();
  const bool pressed = st.proxy.pressed != surgery::Tissue::none && pushed > 0;
  // Tissue: the plane normal to its normal channel (the contacts' push and the pull), with the
  // spring's force less the surface's, shifted towards the device from the proxy's hinge so that
  // the device (the hinge less the offset) is that share's depth at k_d along the normal. The
  // contacts' friction across that normal is left to eq. 18, which renders a sliding tool's drag
  // itself: taken into the normal it would be felt twice.
  if (pressed) {
    haptics::LocalContact& c = m.contacts[m.contact_count++];
    c.normal = st.proxy.normal_force / pushed;
    c.tissue = tissue_kind(st.proxy.pressed);
    const Vec3 share = stopped ? Vec3(spring - st.stop.force) : spring;
    const Real k_tissue = s.params.proxy.stiffness[std::size_t(st.proxy.pressed)];
    if (k > 0 && k_tissue > 0)
      c.point = reference - (offset.dot(c.normal) - share.dot(c.normal) / k_tissue) * c.normal;
    else
      c.point = reference;
  }
  // The heart or the wall: rigid, they stop the proxy where the tool meets them, and the hand
  // feels them at their own k_d: the plane is where they stop it, the device's point the stopped
  // probe point carried by the same lever, so the device's depth past the plane is eq. 17's d.
  if (stopped) {
    haptics::LocalContact& c = m.contacts[m.contact_count++];
    c.point = st.stop.plane;
    c.normal = st.stop.normal;
    c.surface_velocity = st.stop.velocity;
    c.tissue = tissue_kind(st.stop.tissue);
    c.lever = st.stop.point - reference;
  }
  if (station == 1 && st.pedal != surgery::PedalMode::off) {
    m.cautery = st.pedal == surgery::PedalMode::cut ? haptics::CauteryMode::cut
                                                    : haptics::CauteryMode::coag;
    m.power_w = st.power_w;
  }
  // The device's hinge in the scene, from the arm's anchors. A tool pose is used as given, or
  // from its clutch registration's anchors at 1:1.
  const bool registered_tool =
      st.source == surgery::PoseSource::tool && s.params.tool_pose_clutch_registered;
  if (st.source == surgery::PoseSource::hand || registered_tool) {
    m.hand_anchor = st.arm_state.hand_anchor.translation;
    m.tool_anchor = st.arm_state.tool_anchor.translation;
    m.motion_scale = registered_tool ? Real(1) : st.arm.motion_scale;
  }
  return m;
}

}  // namespace imasim::console
