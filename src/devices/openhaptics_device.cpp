#include "devices/openhaptics_device.hpp"

#include <HD/hd.h>

#include <atomic>
#include <stdexcept>

#include "base/latest_value.hpp"

namespace imasim::devices {

namespace {

constexpr Real kMetresPerMillimetre = Real(0.001);

struct StylusState {
  Pose pose;  // (unit: m)
  bool button1 = false, button2 = false;
  bool ok = false;
};

std::string hd_error_text(const HDErrorInfo& e) {
  return std::string(hdGetErrorString(e.errorCode)) + " (code " + std::to_string(e.errorCode) + ")";
}

// The scheduler is shared by every device of the process: started with the first, stopped
// with the last.
std::atomic<int> scheduler_users{0};

}  // namespace

struct OpenHapticsDevice::Servo {
  HHD device = HD_INVALID_HANDLE;
  HDSchedulerHandle callback = HD_INVALID_HANDLE;
  Real max_force = Real(3.3);
  base::LatestValue<StylusState> state;  // servo -> loop
  base::LatestValue<Vec3> force;         // loop -> servo
  Vec3 servo_force = Vec3::Zero();       // servo thread only
  StylusState loop_state;                // loop thread only
  std::atomic<bool> failed{false};
};

namespace {

HDCallbackCode HDCALLBACK servo_tick(void* data) {
  auto* s = static_cast<OpenHapticsDevice::Servo*>(data);
  hdMakeCurrentDevice(s->device);
  hdBeginFrame(s->device);
  HDdouble m[16];
  HDint buttons = 0;
  hdGetDoublev(HD_CURRENT_TRANSFORM, m);  // column-major, translation in millimetres
  hdGetIntegerv(HD_CURRENT_BUTTONS, &buttons);
  s->force.read(s->servo_force);
  const HDdouble f[3] = {s->servo_force.x(), s->servo_force.y(), s->servo_force.z()};
  hdSetDoublev(HD_CURRENT_FORCE, f);
  hdEndFrame(s->device);
  StylusState out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      out.pose.rotation(i, j) = Real(m[4 * j + i]);
    out.pose.translation(i) = Real(m[12 + i]) * kMetresPerMillimetre;
  }
  out.button1 = (buttons & HD_DEVICE_BUTTON_1) != 0;
  out.button2 = (buttons & HD_DEVICE_BUTTON_2) != 0;
  const HDErrorInfo e = hdGetError();
  out.ok = !HD_DEVICE_ERROR(e);
  if (!out.ok) s->failed = true;
  s->state.publish(out);
  return HD_CALLBACK_CONTINUE;
}

}  // namespace

OpenHapticsDevice::OpenHapticsDevice(const std::string& device_name, Hand hand)
    : name_(device_name), hand_(hand), servo_(std::make_unique<Servo>()) {
  servo_->device = hdInitDevice(device_name.c_str());
  HDErrorInfo e = hdGetError();
  if (HD_DEVICE_ERROR(e))
    throw std::runtime_error("OpenHaptics: cannot open '" + device_name + "': " + hd_error_text(e));
  HDdouble max = 0;
  hdGetDoublev(HD_NOMINAL_MAX_FORCE, &max);
  if (max > 0) servo_->max_force = Real(max);
  hdEnable(HD_FORCE_OUTPUT);
  servo_->callback = hdScheduleAsynchronous(servo_tick, servo_.get(), HD_MAX_SCHEDULER_PRIORITY);
  if (scheduler_users++ == 0) hdStartScheduler();
  e = hdGetError();
  if (HD_DEVICE_ERROR(e)) {
    hdUnschedule(servo_->callback);
    if (--scheduler_users == 0) hdStopScheduler();
    hdDisableDevice(servo_->device);
    throw std::runtime_error("OpenHaptics: cannot start the servo loop: " + hd_error_text(e));
  }
}

OpenHapticsDevice::~OpenHapticsDevice() {
  servo_->force.publish(Vec3::Zero());
  if (--scheduler_users == 0) hdStopScheduler();
  hdUnschedule(servo_->callback);
  hdDisableDevice(servo_->device);
}

void OpenHapticsDevice::poll(double now_s, ConsoleInput& input) {
  if (!servo_->state.read(servo_->loop_state) || !servo_->loop_state.ok) return;
  HandInput& h = input.hand(hand_);
  const StylusState& s = servo_->loop_state;
  if (h.has_pose && now_s > h.time_s)
    h.velocity = (s.pose.translation - h.pose.translation) / Real(now_s - h.time_s);
  h.pose = s.pose;
  h.frame = PoseFrame::hand;
  h.time_s = now_s;
  h.has_pose = h.has_buttons = true;
  h.jaw = s.button1 ? 1 : 0;
  h.clutch = s.button2;
}

void OpenHapticsDevice::send_force(Hand hand, const Vec3& force_n, double) {
  if (hand != hand_) return;
  // The safety filter already bounds it; the device's own maximum bounds it again.
  Vec3 f = force_n.allFinite() ? force_n : Vec3::Zero();
  if (f.norm() > servo_->max_force) f *= servo_->max_force / f.norm();
  servo_->force.publish(f);
}

bool OpenHapticsDevice::connected() const {
  return !servo_->failed.load();
}

DeviceInfo OpenHapticsDevice::info() const {
  DeviceInfo d;
  d.kind = "openhaptics";
  d.name = name_;
  d.mapping = std::string(hand_ == Hand::left ? "left" : "right") +
              " hand: stylus pose (mm, the device's frame); button 1 -> jaw (held = closed), "
              "button 2 -> clutch; force out through the HD servo loop";
  d.connected = connected();
  d.force_feedback = true;
  d.max_force_n = servo_->max_force;
  d.drives_left = hand_ == Hand::left;
  d.drives_right = hand_ == Hand::right;
  return d;
}

}  // namespace imasim::devices
