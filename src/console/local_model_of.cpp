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
  // stopped it, theirs. Each plane is put at the depth its own share of that force explains at its
  // tissue's k_d, so the hand feels the spring once, whichever tissue's k the coupling took
  // (rendered at each plane's k_d, the offset came out once per plane and k_d / k times).
  const Vec3& offset = st.proxy.offset;
  const Real k = st.proxy.coupling;
  const Vec3 spring = k * offset;
  // The plane's shift towards the device from the proxy's hinge that leaves the device (the hinge
  // less the offset) `share`'s depth along `normal` at `k_tissue`; none without a coupling yet.
  auto shift = [&](const Vec3& normal, const Vec3& share, Real k_tissue) -> Vec3 {
    if (!(k > 0 && k_tissue > 0)) return Vec3::Zero();
    return (offset.dot(normal) - share.dot(normal) / k_tissue) * normal;
  };
  const bool stopped = st.stop.tissue != surgery::Tissue::none;
  const Real pushed = st.proxy.normal_force.norm();
  const bool pressed = st.proxy.pressed != surgery::Tissue::none && pushed > 0;
  // Tissue: the plane normal to its normal channel (the contacts' push and the pull), with the
  // spring's force less the surface's. The contacts' friction across that normal is left to
  // eq. 18, which renders a sliding tool's drag itself: taken into the normal it would be felt
  // twice.
  if (pressed) {
    haptics::LocalContact& c = m.contacts[m.contact_count++];
    c.normal = st.proxy.normal_force / pushed;
    c.tissue = tissue_kind(st.proxy.pressed);
    const Vec3 share = stopped ? Vec3(spring - st.stop.force) : spring;
    c.point =
        reference - shift(c.normal, share, s.params.proxy.stiffness[std::size_t(st.proxy.pressed)]);
  }
  // The heart or the wall: their surface where they stop the proxy, the device's point there
  // carried by the same lever; beside the tissue with their own force, alone with the spring's.
  if (stopped) {
    haptics::LocalContact& c = m.contacts[m.contact_count++];
    c.point = st.stop.point;
    c.normal = st.stop.normal;
    c.surface_velocity = st.stop.velocity;
    c.tissue = tissue_kind(st.stop.tissue);
    const Vec3 share = pressed ? st.stop.force : spring;
    c.lever = st.stop.point - reference +
              shift(c.normal, share, s.params.proxy.stiffness[std::size_t(st.stop.tissue)]);
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
