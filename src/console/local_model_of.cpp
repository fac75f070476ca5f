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
  // Tissue: the proxy sits where the tissue's force balances the coupling, so the plane through
  // the proxy's hinge normal to its normal channel (the contacts' push and the pull) puts the
  // device k_d d behind it. The contacts' friction across that normal is left to eq. 18, which
  // renders a sliding tool's drag itself: taken into the normal it would be felt twice.
  const Real pushed = st.proxy.normal_force.norm();
  if (st.proxy.pressed != surgery::Tissue::none && pushed > 0) {
    haptics::LocalContact& c = m.contacts[m.contact_count++];
    c.point = reference;
    c.normal = st.proxy.normal_force / pushed;
    c.tissue = tissue_kind(st.proxy.pressed);
  }
  // The heart or the wall: their surface where they stop the proxy, the device's point there
  // carried by the same lever.
  if (st.stop.tissue != surgery::Tissue::none) {
    haptics::LocalContact& c = m.contacts[m.contact_count++];
    c.point = st.stop.point;
    c.normal = st.stop.normal;
    c.lever = st.stop.point - reference;
    c.surface_velocity = st.stop.velocity;
    c.tissue = tissue_kind(st.stop.tissue);
  }
  if (station == 1 && st.pedal != surgery::PedalMode::off) {
    m.cautery = st.pedal == surgery::PedalMode::cut ? haptics::CauteryMode::cut
                                                    : haptics::CauteryMode::coag;
    m.power_w = st.power_w;
  }
  // The device's hinge in the scene, from the arm's anchors. A tool pose is used as given.
  if (st.source == surgery::PoseSource::hand) {
    m.hand_anchor = st.arm_state.hand_anchor.translation;
    m.tool_anchor = st.arm_state.tool_anchor.translation;
    m.motion_scale = st.arm.motion_scale;
  }
  return m;
}

}  // namespace imasim::console
