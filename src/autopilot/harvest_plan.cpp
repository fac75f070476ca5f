#include "autopilot/harvest_plan.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "autopilot/working_frame.hpp"

namespace imasim::autopilot {

namespace {

using haptics::CauteryMode;

// Nominal speeds at OperatorParams::speed = 1: the hook cuts at 10 mm/s (as the example script
// does; electrosurgical dissection is slow) and travels at 20 mm/s with the pedal up.
constexpr Real kCutSpeed = Real(0.010);     // (unit: m/s)
constexpr Real kTravelSpeed = Real(0.020);  // (unit: m/s)
constexpr double kMinMove = 0.2;            // the shortest move (unit: s)
// Two incisions open the fascia, this far either side of the vessel's centre: wide enough for
// the hook's wrist to pass beside the vessel while it divides. (Nearer the vessel on the heart's
// side, the strip of fascia left over the vessel is narrower, and drawing the other lip aside
// drags the vessel 3-4 mm onto the hook's electrode: tried for the beating heart, it injured the
// IMA in 2 of 10 patients.)
constexpr Real kIncisionOffset = Real(0.007);  // (unit: m)
// The electrode's tip passes this far beyond the fascia towards the wall while it opens it.
constexpr Real kIncisionReach = Real(0.0025);  // (unit: m)
// Dividing sweeps: the tip this far beside the vessel's centre and this high over it (towards
// the wall) for a still heart: the fat strands that hold the vessel to the wall fan out from its
// upper half, and there the tip's 4 mm cutting square (eq. 12) crosses most of them while the
// electrode stays 2 mm from the vessel's wall (its heat there is a sixth of that at contact).
constexpr Real kSweepOffset = Real(0.0025);  // (unit: m)
constexpr Real kSweepHeight = Real(0.002);   // (unit: m)
// Each sweep overlaps its neighbours and passes the segment's ends by this: a strand is divided
// when the cutting square's plane passes it, not when the tip reaches it.
constexpr Real kSweepOverlap = Real(0.003);  // (unit: m)
// Then back along the section higher up, under the wall and a little further out, where the
// strands end: it divides what the first sweep pushed aside, 2.8 mm from the vessel's wall.
constexpr Real kReturnOffset = Real(0.003);      // (unit: m)
constexpr Real kReturnBelowWall = Real(0.0015);  // (unit: m)
constexpr Real kWallClearance = Real(0.0015);    // the tip keeps this from the wall (unit: m)
constexpr Real kSectionLength = Real(0.020);     // the segment is divided section by section (m)
constexpr Real kAlongPiece = Real(0.005);        // moves along the vessel follow it in these (m)
constexpr Real kLipOffset = Real(0.003);         // the forceps hold the lip this far out (unit: m)
constexpr Real kRetractAway = Real(0.005);       // the held lip is drawn this far out ...
constexpr Real kRetractDown = Real(0.003);       // ... and this far into the cavity (unit: m)
constexpr Real kBelowFascia = Real(0.003);       // tools wait this far under the fascia (unit: m)
// The hook's wrist raises the electrode towards the wall at this share, the rest leaning across
// the vessel from outside, so that the tip is the electrode's point nearest the vessel.
constexpr Real kHookRise = Real(0.9);
// Flatter rises the hook is laid at, in turn, where the upright one comes too near the heart.
constexpr std::array<Real, 4> kFlatterRises = {Real(0.8), Real(0.7), Real(0.6), Real(0.5)};
// The generator's power: 40 W to open the fascia, the lowest setting (30 W) beside the vessel,
// where less heat spreads to its wall.
constexpr Real kOpeningPower = 40;   // (unit: W)
constexpr Real kDividingPower = 30;  // (unit: W)
// Moves that keep the heart at bay go up (out of the cavity) in steps of this (unit: m).
constexpr Real kClearanceStep = Real(0.00025);

// A rotation whose f axis (col 2) is `f` and whose n axis (col 1) is `n` made perpendicular to
// it; l = n x f (col 0).
Mat3 tool_rotation(const Vec3& f_in, const Vec3& n_in) {
  const Vec3 f = f_in.normalized();
  Vec3 n = n_in - n_in.dot(f) * f;
  if (n.squaredNorm() < Real(1e-12)) n = f.unitOrthogonal();
  n.normalize();
  Mat3 r;
  r.col(0) = n.cross(f);
  r.col(1) = n;
  r.col(2) = f;
  return r;
}

class Planner {
 public:
  Planner(const WorkingFrame& frame, const OperatorParams& p, Real electrode)
      : w_(frame), p_(p), electrode_(electrode) {
    keep_out_ = p.keep_out_base + p.keep_out_gain * frame.heart_excursion;
    // The further it keeps from the heart, the higher it works: up to the wall's clearance.
    sweep_height_ =
        std::min(kSweepHeight + (keep_out_ - p.keep_out_base), frame.wall_height - kWallClearance);
    forceps_ = {0, frame.forceps_start, 0};
    hook_ = {0, frame.hook_start, 0};
    plan_.forceps.push_back(forceps_);
    plan_.hook.push_back(hook_);
    plan_.pedal.push_back({0, CauteryMode::off});
    plan_.segment = frame.segment;
    plan_.heart_excursion = frame.heart_excursion;
    plan_.keep_out = keep_out_;
    plan_.electrode_length = electrode;
  }

  HarvestPlan finish() {
    plan_.end_time = std::max(plan_.forceps.back().time, plan_.hook.back().time);
    return std::move(plan_);
  }

  void phase(const std::string& name) { plan_.phases.push_back({now(), name}); }

  // The point at arc length s, `across` beside the vessel away from the heart (< 0: towards
  // it, shifted by the side bias) and `up` towards the wall.
  Vec3 at(Real s, Real across, Real up) const {
    // Beyond the segment's ends, along its end tangents.
    const Real inside = std::clamp(s, Real(0), length());
    return w_.point_at(inside) + (s - inside) * w_.tangent_at(inside) +
           (across + p_.side_bias) * w_.away + up * w_.wall_normal;
  }
  Real length() const { return w_.length(); }
  Real fascia_depth() const { return w_.fascia_depth; }
  Real wall_height() const { return w_.wall_height; }
  Real sweep_height() const { return sweep_height_; }

  // How far the hook's electrode rises towards the wall (the share of its length; the rest leans
  // in from outside) while its tip goes from arc length a to b, `across` (its side: away from
  // the heart or towards it) and `up`. Upright (kHookRise) unless the heart comes so near the
  // wall that the upright electrode cannot keep even the base margin from it somewhere on the
  // way: then the operator lays the hook flatter, as a surgeon turns the wrist to fit a hook into
  // a narrow space (an upright electrode spanning the gap would wedge between the heart and the
  // wall), at the rise that keeps the whole way furthest from the heart. One rise for the way:
  // between poses laid at different rises the shaft would swing through the narrow space.
  Real rise_along(Real a, Real b, Real across, Real up) const {
    Real best_rise = kHookRise, best_margin = margin_along(a, b, across, up, kHookRise);
    if (best_margin >= p_.keep_out_base) return best_rise;
    for (const Real rise : kFlatterRises) {
      if (const Real margin = margin_along(a, b, across, up, rise); margin > best_margin) {
        best_rise = rise;
        best_margin = margin;
      }
      if (best_margin >= keep_out_) break;
    }
    return best_rise;
  }
  Real margin_along(Real a, Real b, Real across, Real up, Real rise) const {
    const int n = pieces(a, b);
    Real margin = std::numeric_limits<Real>::max();
    for (int i = 0; i <= n; ++i) {
      const Real s = a + (b - a) * Real(i) / Real(n);
      margin = std::min(margin, heart_margin(hook_pose(at(s, across, up), side_of(across),
                                                       w_.tangent_at(s), rise)));
    }
    return margin;
  }
  static int pieces(Real a, Real b) {
    return std::max(1, int(std::ceil(std::abs(b - a) / kAlongPiece)));
  }
  static Real side_of(Real across) { return across < 0 ? Real(-1) : Real(1); }

  // The hook with its tip at `tip`, its electrode rising towards the wall at the share `rise`
  // and leaning in from outside on the side `side`, cutting along `direction` (the cut plane's
  // normal is the motion), raised clear of the heart where the wall leaves room.
  Pose hook_pose(const Vec3& tip, Real side, const Vec3& direction, Real rise) const {
    const Vec3 f = rise * w_.wall_normal - std::sqrt(1 - rise * rise) * side * w_.away;
    Pose pose;
    pose.rotation = tool_rotation(f, direction);
    pose.translation = tip - electrode_ * pose.rotation.col(2);
    // The wrist bends only so far from the shaft (robotic_arm.hpp): place the hinge so that the
    // electrode the arm can give puts its tip on `tip` (a few fixed-point rounds converge: the
    // shaft's direction changes little with the hinge's small moves).
    for (int round = 0; round < 8; ++round) {
      const Pose reached = surgery::constrain_to_port(w_.hook_arm, pose);
      pose.translation = tip - electrode_ * reached.rotation.col(2);
    }
    return clear_of_heart(pose, electrode_);
  }

  // The least distance from the heart's static surface of the hook's hinge, its electrode's
  // middle and its tip, as the arm places it (unit: m).
  Real heart_margin(const Pose& hook) const {
    const Pose reached = surgery::constrain_to_port(w_.hook_arm, hook);
    const Vec3 f = reached.rotation.col(2);
    Real margin = std::numeric_limits<Real>::max();
    for (const Real along : {Real(0), Real(0.5), Real(1)})
      margin = std::min(margin, w_.heart_distance(reached.translation + along * electrode_ * f));
    return margin;
  }

  // The forceps lying in the fascia's plane along the vessel (jaws opening across the fascia),
  // their jaws' middle at `grip`.
  Pose forceps_pose(const Vec3& grip) const {
    constexpr Real kGripDepth = Real(0.006);  // hinge to the middle of what is held (unit: m)
    Pose pose;
    pose.rotation = tool_rotation(w_.tangent_at(length() / 2), w_.wall_normal);
    pose.translation = grip - kGripDepth * pose.rotation.col(2);
    return clear_of_heart(pose, 2 * kGripDepth);
  }

  // Raises a tool (out of the cavity, along the wall's normal) until its hinge and the point
  // `reach` along f keep `keep_out` from the heart's static surface, the operator's margin for
  // the heart (its motion is in keep_out), but never so high that the point passes within the
  // wall clearance of the wall.
  Pose clear_of_heart(Pose pose, Real reach) const {
    const auto clear = [&](const Pose& q) {
      return w_.heart_distance(q.translation) >= keep_out_ &&
             w_.heart_distance(q.translation + reach * q.rotation.col(2)) >= keep_out_;
    };
    const Vec3 centre = w_.point_at(length() / 2);
    const auto height = [&](const Pose& q) {
      return (q.translation + reach * q.rotation.col(2) - centre).dot(w_.wall_normal);
    };
    while (!clear(pose) && height(pose) + kClearanceStep <= w_.wall_height - kWallClearance)
      pose.translation += kClearanceStep * w_.wall_normal;
    return pose;
  }

  void move_hook(const Pose& to, Real speed, double at_least = kMinMove) {
    hook_ = {hook_.time + duration(hook_.tool, to, speed, at_least), to, 0};
    plan_.hook.push_back(hook_);
  }
  void move_forceps(const Pose& to, Real jaw, Real speed, double at_least = kMinMove) {
    forceps_ = {forceps_.time + duration(forceps_.tool, to, speed, at_least), to, jaw};
    plan_.forceps.push_back(forceps_);
  }
  void hold_forceps(Real jaw, double seconds) {
    forceps_.time += seconds / double(p_.speed);
    forceps_.jaw = jaw;
    plan_.forceps.push_back(forceps_);
  }
  void pedal(CauteryMode mode, Real power_w = kOpeningPower) {
    plan_.pedal.push_back({hook_.time, mode, power_w});
  }
  // Both hands continue from the later of their clocks.
  void sync() {
    const double t = now();
    if (hook_.time < t) {
      hook_.time = t;
      plan_.hook.push_back(hook_);
    }
    if (forceps_.time < t) {
      forceps_.time = t;
      plan_.forceps.push_back(forceps_);
    }
  }
  double now() const { return std::max(hook_.time, forceps_.time); }

  // The hook's tip to arc length s, `across` and `up`, moving along the vessel (its cut plane
  // faces along the vessel), with the pedal as it is.
  void hook_to(Real s, Real across, Real up, Real speed) {
    hook_to(s, across, up, speed, kHookRise);
  }
  void hook_to(Real s, Real across, Real up, Real speed, Real rise) {
    move_hook(hook_pose(at(s, across, up), side_of(across), w_.tangent_at(s), rise), speed);
  }
  // The hook cuts from arc length a to b, `across` and `up` from the vessel's centre, in pieces
  // that follow the vessel's course. Only a sweep that divides strands (`dividing`) may lay the
  // hook flatter: in an incision the electrode crosses the fascia, and the blade's swept area
  // is what it cuts there (fascia_cut.hpp), so a flatter blade would open a band, not a line.
  // (Measured with the incisions flatter too: 17 of 20 trials finished against 18.)
  void hook_cut(Real a, Real b, Real across, Real up, Real power_w, bool dividing) {
    const Real rise = dividing ? rise_along(a, b, across, up) : kHookRise;
    hook_to(a, across, up, kTravelSpeed, rise);
    pedal(CauteryMode::cut, power_w);
    hook_along(a, b, across, up, kCutSpeed, rise);
    pedal(CauteryMode::off);
  }
  // From arc length a to b, `across` and `up`, at one rise, in pieces that follow the vessel's
  // course: a straight chord along a curved vessel would pass nearer the heart than the plan.
  void hook_along(Real a, Real b, Real across, Real up, Real speed, Real rise) {
    const int n = pieces(a, b);
    for (int i = 1; i <= n; ++i)
      hook_to(a + (b - a) * Real(i) / Real(n), across, up, speed, rise);
  }
  // From one side of the vessel to the other at the segment's proximal end, where the heart is
  // furthest: down through this side's incision, across under the fascia, up through the other.
  void hook_cross(Real from_across, Real to_across, Real in_gap, Real below) {
    hook_to(0, from_across, in_gap, kTravelSpeed);
    hook_to(0, from_across, below, kTravelSpeed);
    hook_to(0, to_across, below, kTravelSpeed);
    hook_to(0, to_across, in_gap, kTravelSpeed);
  }
  // Back from the distal to the proximal end along an open incision, the pedal on cut so that
  // the electrode parts whatever it meets there (the incision's line is already cut).
  void hook_back_along(Real across, Real in_gap) {
    pedal(CauteryMode::cut);
    hook_along(length(), 0, across, in_gap, kTravelSpeed, kHookRise);
    pedal(CauteryMode::off);
  }

 private:
  double duration(const Pose& from, const Pose& to, Real speed, double at_least) const {
    const double d = double((to.translation - from.translation).norm());
    return std::max(d / double(speed), at_least) / double(p_.speed);
  }

  const WorkingFrame& w_;
  const OperatorParams& p_;
  Real electrode_;
  Real keep_out_ = 0, sweep_height_ = 0;
  ToolKey forceps_, hook_;
  HarvestPlan plan_;
};

void check(const OperatorParams& p) {
  const auto finite_in = [](Real v, Real lo, Real hi) {
    return std::isfinite(v) && v >= lo && v <= hi;
  };
  if (!finite_in(p.speed, Real(0.1), Real(10)))
    throw std::invalid_argument("operator speed must be within [0.1, 10]");
  if (!finite_in(p.side_bias, Real(-0.005), Real(0.005)))
    throw std::invalid_argument("operator side bias must be within [-0.005, 0.005] m");
  if (!finite_in(p.tremor, 0, Real(0.002)))
    throw std::invalid_argument("operator tremor must be within [0, 0.002] m");
  if (!finite_in(p.keep_out_base, 0, Real(0.02)) || !finite_in(p.keep_out_gain, 0, Real(10)))
    throw std::invalid_argument("keep-out base within [0, 0.02] m and gain within [0, 10]");
}

}  // namespace

HarvestPlan plan_harvest(const session::SurgicalSession& session, const OperatorParams& params) {
  check(params);
  const WorkingFrame frame = make_working_frame(session, params.segment_length);
  Planner p(frame, params, session.params.cautery.electrode_length);
  const Real below = -(p.fascia_depth() + kBelowFascia);
  const Real in_gap = -(p.fascia_depth() - kIncisionReach);
  const Real fascia = -p.fascia_depth();
  const Real away = kIncisionOffset, heart_side = -kIncisionOffset;

  // 1. Open the fascia beside the vessel, proximal to distal: on the side away from the heart,
  // then (crossing under the fascia at the proximal end) on the heart's side.
  p.phase("open");
  p.hook_to(0, away, below, kTravelSpeed);
  p.hook_cut(0, p.length(), away, in_gap, kOpeningPower, false);
  p.hook_back_along(away, in_gap);
  p.hook_cross(away, heart_side, in_gap, below);
  p.hook_cut(0, p.length(), heart_side, in_gap, kOpeningPower, false);
  p.hook_back_along(heart_side, in_gap);
  p.hook_cross(heart_side, away, in_gap, below);

  // 2. On each side, away from the heart first, proximal to distal in 2 cm sections: the
  // forceps hold the incision's outer lip aside and the hook divides the fat that holds the
  // vessel to the wall. With those strands divided the pedicle is free.
  p.sync();
  p.phase("divide");
  const int sections = std::max(1, int(std::lround(p.length() / kSectionLength)));
  for (const Real side : {Real(1), Real(-1)}) {
    const Real lip = side * (kIncisionOffset + kLipOffset);
    // Drawn out, and down only on the side away from the heart.
    const Real drawn = lip + side * kRetractAway;
    const Real drawn_up = side > 0 ? fascia - kRetractDown : fascia;
    if (side < 0) {
      p.hook_back_along(away, in_gap);
      p.hook_cross(away, heart_side, in_gap, below);
    }
    for (int k = 0; k < sections; ++k) {
      const Real a = p.length() * Real(k) / Real(sections);
      const Real b = p.length() * Real(k + 1) / Real(sections);
      const Real grip = (a + b) / 2;
      p.move_forceps(p.forceps_pose(p.at(grip, lip, fascia)), 0, kTravelSpeed);
      p.hold_forceps(1, 0.4);  // close on the lip
      p.move_forceps(p.forceps_pose(p.at(grip, drawn, drawn_up)), 1, kTravelSpeed);
      p.sync();
      p.hook_cut(a - kSweepOverlap, b + kSweepOverlap, side * kSweepOffset, p.sweep_height(),
                 kDividingPower, true);
      p.hook_cut(b + kSweepOverlap, a - kSweepOverlap, side * kReturnOffset,
                 p.wall_height() - kReturnBelowWall, kDividingPower, true);
      p.sync();
      p.hold_forceps(0, 0.4);  // release
    }
    p.hook_to(p.length(), side * kIncisionOffset, in_gap, kTravelSpeed);
  }

  // 3. Withdraw both tools under the fascia, clear of the freed pedicle.
  p.sync();
  p.phase("withdraw");
  p.hook_to(p.length(), heart_side, below, kTravelSpeed);
  p.move_forceps(p.forceps_pose(p.at(p.length(), away + kLipOffset, below)), 0, kTravelSpeed);
  p.sync();
  p.phase("done");
  return p.finish();
}

}  // namespace imasim::autopilot
