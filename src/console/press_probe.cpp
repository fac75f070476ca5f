#include "console/press_probe.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "console/console_settings_use.hpp"
#include "console/local_model_of.hpp"
#include "geometry/closest_point.hpp"
#include "session/surgical_session.hpp"
#include "surgery/robotic_arm.hpp"

namespace imasim::console {
namespace {

using session::Station;
using session::SurgicalSession;

constexpr int kHook = 1;
constexpr std::array<const char*, kPressTissues> kNames = {"fascia", "fat", "ima", "heart", "wall"};

// The electrode's end for a device pose, as the port lets the arm hold it.
Vec3 device_tip(const SurgicalSession& s, const Pose& device) {
  const Station& st = s.stations[kHook];
  const Pose held = surgery::constrain_to_port(st.arm, device);
  const Pose w = held * st.state.local * st.instrument.initial;
  return w.translation + s.params.cautery.electrode_length * w.rotation.col(2);
}

// The device pose whose electrode points along `f` with its end at `tip` (the port may turn f
// within the wrist's limit; the hinge is then moved until the end is where it was asked).
Pose device_pose_for_tip(const SurgicalSession& s, const Vec3& tip, const Vec3& f) {
  Pose d;
  d.rotation = surgery::frame_along(f);
  d.translation = tip - s.params.cautery.electrode_length * f;
  for (int k = 0; k < 8; ++k)
    d.translation += tip - device_tip(s, d);
  return d;
}

session::SessionInput hook_at(const Pose& device) {
  session::SessionInput in;
  in.right.source = surgery::PoseSource::tool;
  in.right.pose = device;
  in.right.jaw = surgery::JawCommand::hold;
  in.right.pedal = surgery::PedalMode::off;
  in.right.power = 0;
  return in;
}

void step_once(SurgicalSession& s, const session::SessionInput& in, physics::Executor& exec,
               std::uint64_t& steps) {
  const physics::StepResult r = session::step_session(s, in, exec);
  ++steps;
  if (r.status != physics::StepStatus::ok)
    throw std::runtime_error("press: the physics step failed at t = " +
                             std::to_string(s.scene.patch.world.state.time) + " s");
}

// Moves the device from `from` to `to` at `speed` (position linear, rotation slerp), one pose a
// step, ending on `to`.
void move_device(SurgicalSession& s, const Pose& from, const Pose& to, Real speed,
                 physics::Executor& exec, std::uint64_t& steps) {
  const Real dt = s.scene.patch.world.model.solver.dt;
  const Real length = (to.translation - from.translation).norm();
  const auto n = std::max<std::int64_t>(1, std::llround(std::ceil(length / (speed * dt))));
  const Eigen::Quaternion<Real> q0(from.rotation), q1(to.rotation);
  for (std::int64_t k = 1; k <= n; ++k) {
    const Real a = Real(k) / Real(n);
    Pose p;
    p.translation = from.translation + a * (to.translation - from.translation);
    p.rotation = q0.slerp(a, q1).toRotationMatrix();
    step_once(s, hook_at(p), exec, steps);
  }
}

// The fascia opened and drawn aside: its particles fixed and carried off the field, the strands
// that hold it to the wall divided (they dissolve, eq. 13).
void take_fascia_away(SurgicalSession& s) {
  tissue::TissueWorld& w = s.scene.patch.world;
  physics::Particles& p = w.state.particles;
  const tissue::MeshObject& fascia = w.meshes[s.scene.patch.fascia];
  const Vec3 away(1, 0, 0);  // (unit: m)
  for (std::uint32_t i = fascia.first_particle; i < fascia.first_particle + fascia.particle_count;
       ++i) {
    p.inverse_mass[i] = 0;
    p.position[i] += away;
    p.predicted[i] = p.position[i];
    p.velocity[i] = Vec3::Zero();
    w.reference[i] += away;
  }
  tissue::StrandSet& set = w.strands[s.scene.patch.fascia_fat];
  for (std::uint32_t i = 0; i < set.strand_count; ++i) {
    if (set.cut[i] != tissue::kStrandIntact) continue;
    for (std::uint32_t j = 0; j < set.segments; ++j)
      w.state.constraints.distance.remove(set.segment_constraint[i * set.segments + j]);
    set.cut[i] = tissue::kStrandDivided;
  }
}

// Out of the tissue: the side facing the cavity (-y), where the instruments come from.
Vec3 facing_cavity(Vec3 n) {
  if (n.y() > 0) n = -n;
  return n.normalized();
}

struct Site {
  Vec3 point = Vec3::Zero(), normal = Vec3::UnitY();
};

// The mesh vertex nearest `target` across (x, z), among those with the lowest y within `band`
// of it when `lowest` (the cavity side of a tube).
Site mesh_site(const SurgicalSession& s, std::uint32_t mesh, const Vec3& target, bool lowest) {
  const tissue::MeshObject& m = s.scene.patch.world.meshes[mesh];
  const std::vector<Vec3>& x = s.scene.patch.world.state.particles.position;
  Real best = std::numeric_limits<Real>::infinity();
  std::uint32_t pick = 0;
  for (std::uint32_t v = 0; v < m.particle_count; ++v) {
    const Vec3 d = x[m.first_particle + v] - target;
    Real score = d.x() * d.x() + d.z() * d.z();
    if (lowest) {
      if (std::abs(d.z()) > Real(0.003)) continue;
      score = x[m.first_particle + v].y();
    }
    if (score < best) best = score, pick = v;
  }
  if (!std::isfinite(best))
    throw std::invalid_argument("press: no vertex of " + m.name + " near the site");
  return {x[m.first_particle + pick], facing_cavity(m.normals[pick])};
}

Site heart_site(const SurgicalSession& s, const Vec3& target) {
  const geometry::TriangleMesh heart = session::static_heart_mesh(s);
  Real best = std::numeric_limits<Real>::infinity();
  Site site;
  for (const geometry::Triangle& t : heart.triangles) {
    const Vec3 &a = heart.vertices[t[0]], &b = heart.vertices[t[1]], &c = heart.vertices[t[2]];
    const geometry::TrianglePoint q = geometry::closest_point_on_triangle(target, a, b, c);
    if (q.distance2 >= best) continue;
    best = q.distance2;
    Vec3 n = (b - a).cross(c - a).normalized();
    if (n.dot(q.point - s.scene.layout.heart_centre) < 0) n = -n;
    site = {q.point, n};
  }
  return site;
}

// The lowest fat particle within 4 mm of the vertical through `target`: the fat's face there.
Site fat_site(const SurgicalSession& s, const Vec3& target) {
  const tissue::TissueWorld& w = s.scene.patch.world;
  const tissue::StrandSet& set = w.strands[s.scene.patch.ima_fat];
  const std::vector<Vec3>& x = w.state.particles.position;
  Real lowest = std::numeric_limits<Real>::infinity();
  for (std::uint32_t k = 0; k < set.particle_count(); ++k) {
    const Vec3& p = x[set.first_particle + k];
    const Real dx = p.x() - target.x(), dz = p.z() - target.z();
    if (dx * dx + dz * dz < Real(1.6e-5)) lowest = std::min(lowest, p.y());
  }
  if (!std::isfinite(lowest)) throw std::invalid_argument("press: no fat beside the IMA");
  return {Vec3(target.x(), lowest, target.z()), -Vec3::UnitY()};
}

// Where along the IMA to press: of the centreline's points in the middle 60 % of its course, the
// one farthest from the heart's centre, so that the heart (1 mm under the fascia at mid-course)
// does not stop the tool before the tissue does.
Vec3 press_station(const SurgicalSession& s) {
  const std::vector<Vec3>& c = s.scene.layout.ima_centerline;
  const std::size_t n = c.size();
  Vec3 pick = s.scene.layout.ima_midpoint;
  Real farthest = -1;
  for (std::size_t k = n / 5; k + n / 5 < n; ++k) {
    const Real d = (c[k] - s.scene.layout.heart_centre).squaredNorm();
    if (d > farthest) farthest = d, pick = c[k];
  }
  return pick;
}

Site find_site(const SurgicalSession& s, PressTissue tissue) {
  const scene::ThoraxScene& sc = s.scene;
  const Vec3 station = press_station(s);
  switch (tissue) {
    case PressTissue::fascia:
      return mesh_site(s, sc.patch.fascia, station, false);
    case PressTissue::ima:
      return mesh_site(s, sc.patch.ima, station, true);
    case PressTissue::fat:
      return fat_site(s, station + Vec3(Real(0.004), 0, 0));
    case PressTissue::heart:  // the side facing the hook's port, clear of the other tissues
      return heart_site(s, s.stations[kHook].arm.port);
    case PressTissue::wall:
      return mesh_site(s, sc.patch.wall,
                       station + Vec3(sc.patient.fascia_width / 2 + Real(0.01), 0, 0), false);
  }
  return {};
}

haptics::TissueKind kind_of(PressTissue t) {
  switch (t) {
    case PressTissue::fascia:
      return haptics::TissueKind::fascia;
    case PressTissue::fat:
      return haptics::TissueKind::fat;
    case PressTissue::ima:
      return haptics::TissueKind::ima;
    case PressTissue::heart:
      return haptics::TissueKind::heart;
    case PressTissue::wall:
      return haptics::TissueKind::chest_wall;
  }
  return haptics::TissueKind::fascia;
}

// What the device receives with the hand still at the device pose (trajectory_sample's reading).
haptics::ForceChannels received(const SurgicalSession& s, const haptics::ForceModelParams& forces) {
  const double now = s.scene.patch.world.state.time;
  haptics::LocalModel m = local_model_of(s, kHook, now, 0);
  m.hand_anchor = m.tool_anchor = Vec3::Zero();
  m.motion_scale = 1;
  haptics::DeviceTip tip;
  tip.position = s.stations[kHook].device.translation;
  return haptics::evaluate_local_model(m, forces, tip, now);
}

}  // namespace

const char* press_tissue_name(PressTissue tissue) {
  return kNames[std::size_t(tissue)];
}

std::optional<PressTissue> press_tissue_named(std::string_view name) {
  for (std::size_t k = 0; k < kPressTissues; ++k)
    if (name == kNames[k]) return PressTissue(k);
  return std::nullopt;
}

PressResult press_tissue(const scene::ThoraxSceneParams& given, PressTissue tissue,
                         std::span<const double> depths_m, const PressSettings& settings,
                         physics::Executor& exec) {
  std::vector<double> depths(depths_m.begin(), depths_m.end());
  for (const double d : depths)
    if (!(d > 0 && d <= 0.015))
      throw std::invalid_argument("press: a depth of " + std::to_string(d * 1e3) +
                                  " mm is outside (0, 15] mm");
  std::sort(depths.begin(), depths.end());
  scene::ThoraxSceneParams params = given;
  params.playback.beating = false;
  SurgicalSession s = session::make_surgical_session(params, session::SessionParams{});
  const haptics::ForceModelParams forces = force_model_params(params.console);
  const Real dt = s.scene.patch.world.model.solver.dt;
  PressResult out;
  out.tissue = tissue;
  out.k_d = forces.of(kind_of(tissue)).stiffness;

  // Settle the scene with the hook where it starts (its fascia away first, for the tissues under
  // it), then find the resting surface.
  if (tissue == PressTissue::ima || tissue == PressTissue::fat) take_fascia_away(s);
  const Pose start = s.stations[kHook].device;
  const auto settle_steps = std::llround(settings.settle_s / double(dt));
  for (std::int64_t k = 0; k < 2 * settle_steps; ++k)
    step_once(s, hook_at(start), exec, out.steps);
  Site site = find_site(s, tissue);
  // The instruments keep their clearance from the heart and the chest wall: their surface, for
  // the tool, is that far out.
  if (tissue == PressTissue::heart || tissue == PressTissue::wall)
    site.point += s.params.tool_clearance * site.normal;
  out.site = site.point;
  out.normal = site.normal;

  const Vec3 in = -site.normal;
  const Pose approach = device_pose_for_tip(s, site.point - settings.clearance * in, in);
  move_device(s, s.stations[kHook].device, approach, settings.approach_speed, exec, out.steps);
  const auto average_steps = std::max<std::int64_t>(1, std::llround(settings.average_s / dt));
  Pose at = approach;
  for (const double depth : depths) {
    const Pose target = device_pose_for_tip(s, site.point + Real(depth) * in, in);
    move_device(s, at, target, settings.press_speed, exec, out.steps);
    at = target;
    PressPoint p;
    for (std::int64_t k = 0; k < settle_steps; ++k) {
      step_once(s, hook_at(target), exec, out.steps);
      if (k < settle_steps - average_steps) continue;
      const haptics::ForceChannels f = received(s, forces);
      p.force_n += f.normal_n;
      p.force_along_press_n -= (f.normal + f.tangential).dot(in);
    }
    p.force_n /= double(average_steps);
    p.force_along_press_n /= double(average_steps);
    p.depth_m = (device_tip(s, s.stations[kHook].device) - site.point).dot(in);
    p.law_n = std::clamp(double(out.k_d) * p.depth_m, 0.0, double(haptics::kMaxNormalForce));
    p.proxy_depth_m = (session::electrode(s)[1] - site.point).dot(in);
    out.points.push_back(p);
  }
  return out;
}

}  // namespace imasim::console
