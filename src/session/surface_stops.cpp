#include "session/surface_stops.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace imasim::session {

namespace {

using surgery::Tissue;

// The heart's distance field is searched this far around a point (unit: m).
constexpr Real kHeartSearch = Real(0.01);
// A commanded motion is checked at least every this along its way, so that no step passes
// through the heart or the wall between two free poses (unit: m).
constexpr Real kSweepSpacing = Real(0.001);
// Bisection rounds that find where a motion meets a surface (a 2^-12 share of a sweep piece).
constexpr int kContactRounds = 12;
// Rounds that push an instrument the heart moved into back out (the port turns the shaft as the
// hinge moves, so one round can leave it a little inside).
constexpr int kPushRounds = 8;
// An instrument slides along the surface that stopped it in moves of this, at most this many a
// step: up to 0.5 mm a step (0.1 m/s at the 5 ms step), five times the operator's travel. Faster,
// a hook stopped for seconds would sweep through the tissue beside the heart at metres a second,
// and the tool's contact would fling the fascia's particles.
constexpr Real kSlideStep = Real(0.00025);  // (unit: m)
constexpr int kSlideMoves = 2;
// Beyond the clearance, so that the next check passes (unit: m).
constexpr Real kSlack = Real(1e-5);

Vec3 wall_radial(const geometry::CylinderPatchSpec& wall, const Vec3& x) {
  const Vec3 axis = wall.axis.normalized();
  const Vec3 r = x - wall.origin;
  return r - r.dot(axis) * axis;
}

// How far x is outside the heart (if `heart`) or inside the cavity from the chest wall (unit: m).
Real surface_clearance(SurgicalSession& s, bool heart, const Vec3& x) {
  const geometry::CylinderPatchSpec& wall = s.scene.layout.wall;
  return heart ? tissue::heart_signed_distance(s.scene.heart, x, kHeartSearch)
               : wall.radius - wall_radial(wall, x).norm();
}

// Where an instrument rests against the heart (if `heart`) or else the chest wall: its probe
// point nearest that surface and the surface's outward normal there (the heart's from central
// differences of its signed distance, the wall's towards the cavity's axis).
SurfaceStop surface_stop(SurgicalSession& s, const Station& st, bool heart) {
  SurfaceStop stop;
  stop.tissue = heart ? Tissue::heart : Tissue::chest_wall;
  auto clearance = [&](const Vec3& x) { return surface_clearance(s, heart, x); };
  Real best = std::numeric_limits<Real>::max();
  for (const Vec3& x : probe_points(st, s.params.cautery.electrode_length)) {
    const Real c = clearance(x);
    if (c < best) {
      best = c;
      stop.point = x;
    }
  }
  Vec3 n = Vec3::Zero();
  if (heart) {
    constexpr Real e = Real(2e-4);  // (unit: m)
    for (int k = 0; k < 3; ++k) {
      const Vec3 step = e * Vec3::Unit(k);
      n[k] = clearance(stop.point + step) - clearance(stop.point - step);
    }
  } else {
    n = -wall_radial(s.scene.layout.wall, stop.point);
  }
  if (n.norm() > 0) stop.normal = n.normalized();
  stop.plane = stop.point;  // the guard leaves the point at the clearance
  if (heart) {
    stop.velocity = tissue::heart_surface_velocity(s.scene.heart, stop.point, kHeartSearch);
  }
  return stop;
}

class Stopper {
 public:
  Stopper(SurgicalSession& s, Station& st)
      : s_(s),
        st_(st),
        clearance_(s.params.tool_clearance),
        electrode_(s.params.cautery.electrode_length) {}

  // Whether a probe point of the instrument as placed keeps less than the clearance from the
  // heart or the wall, and which.
  bool blocked(bool& heart, bool& wall) const {
    heart = wall = false;
    const geometry::CylinderPatchSpec& w = s_.scene.layout.wall;
    const std::array<Vec3, 3> probes = probe_points(st_, electrode_);
    for (std::size_t k = 0; k < probes.size(); ++k) {
      heart = heart || nearer_the_heart_than(s_.scene.heart, st_.heart_probes, k, probes[k],
                                             clearance_, kHeartSearch);
      wall = wall || wall_radial(w, probes[k]).norm() >= w.radius - clearance_;
    }
    return heart || wall;
  }
  bool blocked() const {
    bool heart = false, wall = false;
    return blocked(heart, wall);
  }

  void place(const Pose& controller) {
    st_.state.controller = controller;
    st_.pose = surgery::world_pose(st_.instrument, st_.state);
  }

  // The controller pose a share t of the way from a to b, through the port.
  Pose between(const Pose& a, const Pose& b, Real t) const {
    Pose p;
    p.translation = (1 - t) * a.translation + t * b.translation;
    const Eigen::Quaternion<Real> qa(a.rotation), qb(b.rotation);
    p.rotation = qa.slerp(t, qb).toRotationMatrix();
    return surgery::constrain_to_port(st_.arm, p);
  }

  // The surface pushes the instrument as placed out along its normal at the probe point deepest
  // in it, as far as it needs: a god-object rides on a moving surface. (Drawing it back along
  // its shaft instead could take it centimetres back where the shaft runs along the heart.)
  void push_out() {
    for (int round = 0; round < kPushRounds; ++round) {
      bool heart = false, wall = false;
      if (!blocked(heart, wall)) return;
      const SurfaceStop stop = surface_stop(s_, st_, heart);
      const Real depth = clearance_ - surface_clearance(s_, heart, stop.point);
      if (!(depth > 0)) return;
      Pose moved = st_.state.controller;
      moved.translation += (depth + kSlack) * stop.normal;
      place(surgery::constrain_to_port(st_.arm, moved));
    }
  }

  // From `from` towards `to` (both through the port): the share of the way that stays free,
  // checked every kSweepSpacing and refined by bisection where it meets a surface (1: all of it).
  // Leaves the instrument placed there; met_heart and met_wall say what stopped it.
  Real advance(const Pose& from, const Pose& to) {
    met_heart = met_wall = false;
    const Real length = (to.translation - from.translation).norm();
    const int pieces = std::max(1, int(std::ceil(length / kSweepSpacing)));
    Real free = 0;
    for (int k = 1; k <= pieces; ++k) {
      const Real t = Real(k) / Real(pieces);
      place(k == pieces ? to : between(from, to, t));
      if (!blocked(met_heart, met_wall)) {
        free = t;
        continue;
      }
      Real stuck = t;
      for (int round = 0; round < kContactRounds; ++round) {
        const Real mid = Real(0.5) * (free + stuck);
        place(between(from, to, mid));
        (blocked() ? stuck : free) = mid;
      }
      place(free == 0 ? from : between(from, to, free));
      return free;
    }
    return 1;
  }

  bool met_heart = false, met_wall = false;

 private:
  SurgicalSession& s_;
  Station& st_;
  Real clearance_, electrode_;
};

}  // namespace

std::array<Vec3, 3> probe_points(const Station& s, Real electrode_length) {
  const Pose& p = s.pose;
  if (s.instrument.kind == surgery::InstrumentKind::forceps) {
    return {p.translation,
            surgery::jaw_tip(s.instrument, surgery::upper_jaw_pose(s.instrument, s.state)),
            surgery::jaw_tip(s.instrument, surgery::lower_jaw_pose(s.instrument, s.state))};
  }
  const Vec3 tip = p.translation + electrode_length * p.rotation.col(2);
  return {p.translation, Real(0.5) * (p.translation + tip), tip};
}

void stop_at_surfaces(SurgicalSession& s, Station& st) {
  st.blocked_by_heart = st.blocked_by_wall = false;
  st.stop = SurfaceStop{};
  Stopper stopper(s, st);
  const Pose commanded = st.state.controller;
  // Most steps: a short motion to a free pose (shorter than the sweep's spacing, it cannot pass
  // through a surface).
  const Real travel = (commanded.translation - st.previous_controller.translation).norm();
  if (travel <= kSweepSpacing && !stopper.blocked()) return;
  // Where it was; if the heart moved into it there, pushed out.
  stopper.place(st.previous_controller);
  stopper.push_out();
  const Pose from = st.state.controller;
  // Towards the commanded pose as far as the surfaces let it ...
  if (stopper.advance(from, commanded) == 1) return;
  const bool heart = stopper.met_heart, wall = stopper.met_wall;
  // ... then along the surface it met, towards the commanded pose: each move pushed back out to
  // the clearance, while it gets nearer.
  for (int move = 0; move < kSlideMoves; ++move) {
    const Pose at = st.state.controller;
    const Real left = (commanded.translation - at.translation).norm();
    if (left <= kSlack) break;
    stopper.place(stopper.between(at, commanded, std::min(Real(1), kSlideStep / left)));
    stopper.push_out();
    const Real now_left = (commanded.translation - st.state.controller.translation).norm();
    if (stopper.blocked() || now_left > left - kSlack) {
      stopper.place(at);
      break;
    }
  }
  st.blocked_by_heart = heart;
  st.blocked_by_wall = wall;
  st.stop = surface_stop(s, st, heart);
}

}  // namespace imasim::session
