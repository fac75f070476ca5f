#include "console/trajectory_sample.hpp"

#include <Eigen/Geometry>

#include "console/local_model_of.hpp"
#include "session/tool_tip.hpp"

namespace imasim::console {

metrics::TrajectorySample trajectory_sample(const session::SurgicalSession& s,
                                            const haptics::ForceModelParams& forces) {
  metrics::TrajectorySample out;
  const double now = s.scene.patch.world.state.time;
  const Real dt = s.scene.patch.world.model.solver.dt;
  for (int k = 0; k < 2; ++k) {
    const session::Station& st = s.stations[std::size_t(k)];
    metrics::ToolSample& t = out.tools[std::size_t(k)];
    t.tip = session::tool_tip(s, k);
    const Eigen::Quaternion<Real> q(st.pose.rotation);
    t.orientation = {q.w(), q.x(), q.y(), q.z()};
    t.jaw_angle = st.state.jaw_angle;
    t.device = st.device.translation;
    t.clutch = st.arm_state.clutched;
    t.contact = st.proxy.pressed != surgery::Tissue::none ? st.proxy.pressed : st.stop.tissue;
    // The step's local model with the device given in the scene frame (no hand scaling).
    haptics::LocalModel m = local_model_of(s, k, now, 0);
    m.hand_anchor = m.tool_anchor = Vec3::Zero();
    m.motion_scale = 1;
    haptics::DeviceTip device;
    device.position = st.device.translation;
    device.velocity =
        dt > 0 ? Vec3((st.pose.translation - st.previous_pose.translation) / dt) : Vec3::Zero();
    const haptics::ForceChannels f = haptics::evaluate_local_model(m, forces, device, now);
    t.force_normal = f.normal_n;
    t.force_tangential = f.tangential_n;
    t.force_thermal = f.thermal_n;
  }
  out.time = now;
  out.pedal = s.stations[1].pedal;
  out.power_w = s.stations[1].power_w;
  return out;
}

}  // namespace imasim::console
