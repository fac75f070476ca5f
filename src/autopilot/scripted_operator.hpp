#pragma once
// The scripted operator as a device: it plays a harvest plan through the same
// interface as a surgeon's hands (devices/input_device.hpp): a tool pose per hand (the hinge, as
// a tracker on the instrument reports it), the jaws and the cautery pedal. It never reads or
// writes tissue state. Poses interpolate between the plan's keys (position linearly, rotation by
// slerp) and carry the operator's tremor.
//
// Like a surgeon watching the endoscope, it sees where its instruments are (`observe`: the
// instrument's hinge, which the tissue it presses on pushes away from the hand's pose through the
// tool proxy) and corrects its hands by integrating the error between where it wanted the
// instrument and where it went, within a bounded reach. Everything is a function of time, the
// plan, the seed and what it observed, so a trial is bit-for-bit repeatable.
#include <array>

#include "autopilot/harvest_plan.hpp"
#include "autopilot/tremor.hpp"
#include "devices/input_device.hpp"

namespace imasim::autopilot {

class ScriptedOperator final : public devices::InputDevice {
 public:
  ScriptedOperator(HarvestPlan plan, const OperatorParams& params);

  void poll(double now_s, devices::ConsoleInput& input) override;
  // No force feedback: the operator follows its plan whatever it feels.
  void send_force(devices::Hand, const Vec3&, double) override {}
  bool connected() const override { return true; }
  devices::DeviceInfo info() const override;

  // Where an instrument is now (its hinge and axes in the scene frame; unit: m), for the next
  // poll.
  void observe(devices::Hand hand, const Pose& instrument);

  const HarvestPlan& plan() const { return plan_; }
  bool finished(double now_s) const { return now_s >= plan_.end_time; }
  // The phase under way at a time ("" before the first).
  const std::string& phase_at(double now_s) const;

 private:
  // Per hand: the correction added to the plan, the pose it last asked for (with tremor, before
  // the correction) and what it observed since.
  struct Servo {
    Vec3 correction = Vec3::Zero();  // (unit: m)
    Pose asked, observed;            // (unit: m)
    bool has_asked = false, has_observed = false;
  };
  // Whether the hook is held off its line towards the vessel (the pedal then stays up).
  bool hook_pushed_to_vessel() const;
  HarvestPlan plan_;
  Tremor left_tremor_, right_tremor_;
  std::array<Servo, 2> servo_{};
};

// A key track sampled at t: poses and the jaw interpolated, held outside the keys.
ToolKey sample_tool_track(const std::vector<ToolKey>& track, double t);

}  // namespace imasim::autopilot
