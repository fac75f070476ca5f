#include "py_session.hpp"

#include <stdexcept>

#include "console/console_settings_use.hpp"
#include "console/stream_origin.hpp"
#include "console/trajectory_sample.hpp"
#include "math/state_hash.hpp"
#include "physics/state.hpp"
#include "render/camera.hpp"
#include "render/frame_of_session.hpp"
#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::python {

namespace {

scene::ThoraxSceneParams params_of(const SessionOptions& o) {
  scene::ThoraxSceneParams p = o.scene_file.empty() ? scene::default_thorax_scene_params()
                                                    : scene::load_scene_file(o.scene_file);
  if (o.patient_seed) p.anatomy.patient_seed = *o.patient_seed;
  if (o.static_heart) p.playback.beating = false;
  return p;
}

void check_hand(int hand) {
  if (hand != 0 && hand != 1)
    throw std::invalid_argument("hand " + std::to_string(hand) +
                                ": 0 (forceps, left) or 1 (hook, right)");
}

}  // namespace

int hand_index(const std::string& name) {
  if (name == "forceps" || name == "left" || name == "0") return 0;
  if (name == "hook" || name == "right" || name == "1") return 1;
  throw std::invalid_argument("hand '" + name + "': forceps (left) or hook (right)");
}

PySession::PySession(const SessionOptions& o)
    : params_(params_of(o)),
      forces_(console::force_model_params(params_.console)),
      exec_(o.threads) {
  session_ = std::make_unique<session::SurgicalSession>(
      session::make_surgical_session(params_, session::SessionParams{}));
  runner_ = std::make_unique<runner::SessionRunner>(*session_, input_, exec_);
}

PySession::~PySession() {
  try {
    stop_recording();
  } catch (const metrics::OutputError&) {
    // Nothing to tell from a destructor: the stream ends where its last write did.
  }
}

bool PySession::step(std::uint64_t n) {
  for (std::uint64_t k = 0; k < n; ++k) {
    const runner::StepOutcome out = runner_->step();
    if (!out.output_error.empty()) throw metrics::OutputError(out.output_error);
    if (!out.result.ok()) return false;
  }
  return true;
}

void PySession::record_input(const std::string& path) {
  if (recorder_) throw metrics::OutputError("already recording the input to a stream");
  const std::string program = IMASIM_VERSION;
  recorder_ = std::make_unique<runner::InputStreamRecorder>(
      metrics::OutputFile(path, "the input stream"), console::stream_origin_of(params_, program));
  runner_->observe(*recorder_);
}

void PySession::stop_recording() {
  if (!recorder_) return;
  runner_->forget(*recorder_);
  const std::unique_ptr<runner::InputStreamRecorder> done = std::move(recorder_);
  done->finish(*session_);
}

void PySession::set_device_pose(int hand, const Pose& pose) {
  check_hand(hand);
  surgery::InstrumentInput& in = hand == 0 ? input_.input.left : input_.input.right;
  in.source = surgery::PoseSource::tool;
  in.pose = pose;
}

void PySession::set_jaw(int hand, surgery::JawCommand jaw) {
  check_hand(hand);
  (hand == 0 ? input_.input.left : input_.input.right).jaw = jaw;
}

void PySession::set_pedal(surgery::PedalMode pedal, Real power_w) {
  if (!(power_w >= 0 && power_w <= 120))
    throw std::invalid_argument("power_w " + std::to_string(power_w) + ": 0 to 120 W");
  input_.input.right.pedal = pedal;
  input_.input.right.power = power_w;
}

metrics::TrajectorySample PySession::sample() const {
  return console::trajectory_sample(*session_, forces_);
}

std::string PySession::state_hash() const {
  return to_hex(physics::position_hash(session_->scene.patch.world.state));
}

std::vector<std::uint8_t> PySession::render(int width, int height) const {
  if (width < 16 || height < 16 || width > 4096 || height > 4096)
    throw std::invalid_argument("render: width and height from 16 to 4096 pixels");
  render::OffscreenContext context(width, height);
  render::Renderer renderer;
  render::RenderFrame frame;
  render::frame_of_session(*session_, frame);
  context.bind();
  const render::Camera camera = render::endoscope_camera(frame, float(width) / float(height));
  renderer.draw(frame, camera, {0, 0, width, height});
  return context.read_rgb();
}

double PySession::pedicle_divided() const {
  const tissue::StrandSet& set = session_->scene.patch.world.strands[session_->scene.patch.ima_fat];
  if (set.strand_count == 0) return 0;
  std::uint32_t divided = 0;
  for (std::uint8_t c : set.cut)
    divided += c == tissue::kStrandDivided ? 1 : 0;
  return double(divided) / double(set.strand_count);
}

}  // namespace imasim::python
