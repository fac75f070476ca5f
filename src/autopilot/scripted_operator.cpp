#include "autopilot/scripted_operator.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "autopilot/working_frame.hpp"

namespace imasim::autopilot {

ToolKey sample_tool_track(const std::vector<ToolKey>& track, double t) {
  if (track.empty()) return {};
  const auto after = std::upper_bound(track.begin(), track.end(), t,
                                      [](double time, const ToolKey& k) { return time < k.time; });
  if (after == track.begin()) return track.front();
  if (after == track.end()) return track.back();
  const ToolKey& a = *(after - 1);
  const ToolKey& b = *after;
  const double span = b.time - a.time;
  const Real s = span > 0 ? Real((t - a.time) / span) : Real(1);
  ToolKey out;
  out.time = t;
  out.tool.translation = (1 - s) * a.tool.translation + s * b.tool.translation;
  const Eigen::Quaternion<Real> qa(a.tool.rotation), qb(b.tool.rotation);
  out.tool.rotation = qa.slerp(s, qb).toRotationMatrix();
  out.jaw = (1 - s) * a.jaw + s * b.jaw;
  return out;
}

ScriptedOperator::ScriptedOperator(HarvestPlan plan, const OperatorParams& params)
    : plan_(std::move(plan)),
      left_tremor_(params.seed * 2 + 1, params.tremor),
      right_tremor_(params.seed * 2 + 2, params.tremor) {}

namespace {

// The share of the last step's error the correction takes up each step, and the largest
// correction: a tool the heart or the chest wall stops is not pushed after without end.
constexpr Real kServoGain = Real(0.2);
constexpr Real kMaxCorrection = Real(0.01);  // (unit: m)
// The correction grows by at most this a poll (20 mm/s at the 5 ms step): a tool released by
// what held it back does not jump, and launch the tissue under it.
constexpr Real kMaxCorrectionStep = Real(1e-4);  // (unit: m)
// The operator keeps the pedal up while it sees its hook's hinge further than this from where it
// asked for it (held back by tissue, stopped by the wall) and the electrode's tip nearer the
// vessel than it asked: an electrode is energised only where the surgeon sees it, never where
// tissue pushed it towards the vessel. Held back away from the vessel, the hook is caught on the
// fascia or fat it is dividing, and cutting frees it (with the pedal up it stayed caught there,
// its sweep undone: patient 9 of the study, docs/autopilot.md).
constexpr Real kOffLine = Real(0.0025);  // (unit: m)

}  // namespace

void ScriptedOperator::observe(devices::Hand hand, const Pose& instrument) {
  Servo& s = servo_[hand == devices::Hand::left ? 0 : 1];
  s.observed = instrument;
  s.has_observed = true;
}

bool ScriptedOperator::hook_pushed_to_vessel() const {
  const Servo& hook = servo_[1];
  if (!hook.has_asked || !hook.has_observed) return false;
  if (!((hook.asked.translation - hook.observed.translation).norm() > kOffLine)) return false;
  // The tip as seen, and where it would be with the hinge where the hand asked (the shaft's
  // direction as seen: the port sets it, not the hand).
  const Vec3 along = plan_.electrode_length * hook.observed.rotation.col(2);
  return distance_to_segment(hook.observed.translation + along, plan_.segment) <
         distance_to_segment(hook.asked.translation + along, plan_.segment);
}

void ScriptedOperator::poll(double now_s, devices::ConsoleInput& input) {
  const auto drive = [now_s](const std::vector<ToolKey>& track, const Tremor& tremor, Servo& servo,
                             devices::HandInput& hand) {
    const ToolKey k = sample_tool_track(track, now_s);
    hand.pose = k.tool;
    hand.pose.translation += tremor.at(now_s);
    if (servo.has_asked && servo.has_observed) {
      Vec3 step = kServoGain * (servo.asked.translation - servo.observed.translation);
      if (const Real n = step.norm(); n > kMaxCorrectionStep) step *= kMaxCorrectionStep / n;
      servo.correction += step;
      const Real n = servo.correction.norm();
      if (n > kMaxCorrection) servo.correction *= kMaxCorrection / n;
    }
    servo.asked = hand.pose;
    servo.has_asked = true;
    servo.has_observed = false;
    hand.pose.translation += servo.correction;
    hand.frame = devices::PoseFrame::tool;
    hand.time_s = now_s;
    hand.has_pose = true;
    hand.has_buttons = true;
    hand.clutch = false;
    hand.jaw = k.jaw;
  };
  const bool hook_off_line = hook_pushed_to_vessel();
  drive(plan_.forceps, left_tremor_, servo_[0], input.left);
  drive(plan_.hook, right_tremor_, servo_[1], input.right);
  const auto after = std::upper_bound(plan_.pedal.begin(), plan_.pedal.end(), now_s,
                                      [](double time, const PedalKey& k) { return time < k.time; });
  input.pedal =
      after == plan_.pedal.begin() || hook_off_line ? haptics::CauteryMode::off : (after - 1)->mode;
  input.power_w = after == plan_.pedal.begin() ? Real(40) : (after - 1)->power_w;
}

devices::DeviceInfo ScriptedOperator::info() const {
  devices::DeviceInfo i;
  i.kind = "autopilot";
  i.name = "scripted operator (a test operator, not a model of surgeons)";
  i.mapping = "forceps: tool pose and jaws; hook: tool pose; pedal: cut and coagulation";
  i.connected = true;
  i.drives_left = i.drives_right = i.drives_pedal = true;
  return i;
}

const std::string& ScriptedOperator::phase_at(double now_s) const {
  static const std::string none;
  const auto after =
      std::upper_bound(plan_.phases.begin(), plan_.phases.end(), now_s,
                       [](double time, const PhaseMark& m) { return time < m.time; });
  return after == plan_.phases.begin() ? none : (after - 1)->name;
}

}  // namespace imasim::autopilot
