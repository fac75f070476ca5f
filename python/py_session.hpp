#pragma once
// The simulator as the Python module sees it (docs/python.md): one surgical session stepped by
// the session runner from the input its caller commands, read back as plain values. No Python
// here: module.cpp binds it, so it can be stepped on any thread with the GIL released.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "haptics/force_params.hpp"
#include "metrics/trajectory_recorder.hpp"
#include "physics/executor.hpp"
#include "runner/input_source.hpp"
#include "runner/input_stream_recorder.hpp"
#include "runner/session_runner.hpp"
#include "scene/thorax_scene.hpp"
#include "session/surgical_session.hpp"

namespace imasim::python {

struct SessionOptions {
  std::string scene_file;                     // empty: the built-in thorax
  std::optional<std::uint64_t> patient_seed;  // empty: the scene's
  bool static_heart = false;
  int threads = 1;
};

class PySession {
 public:
  // Throws std::invalid_argument (a scene file that does not load names its file, line and key).
  explicit PySession(const SessionOptions& options);

  // Steps n times with the input last commanded; false when a step was refused (the session
  // stays where that step found it). Throws metrics::OutputError when the input stream being
  // recorded cannot be written.
  bool step(std::uint64_t n);

  // From the next step on, each step's input goes to `path` as an input stream that
  // `imasim run --headless --replay PATH` plays to the same state (console/input_stream.hpp);
  // finished (its end line) by stop_recording or the session's end. Throws metrics::OutputError.
  void record_input(const std::string& path);
  void stop_recording();
  ~PySession();
  PySession(const PySession&) = delete;
  PySession& operator=(const PySession&) = delete;

  // Commands for the coming steps. hand: 0 the forceps (left), 1 the hook (right).
  void set_device_pose(int hand, const Pose& pose);
  void set_jaw(int hand, surgery::JawCommand jaw);
  void set_pedal(surgery::PedalMode pedal, Real power_w);
  const session::SessionInput& commanded() const { return input_.input; }

  const session::SurgicalSession& session() const { return *session_; }
  session::SurgicalSession& session() { return *session_; }
  const scene::ThoraxSceneParams& params() const { return params_; }
  // The instruments' tips, poses and eq. 17-19 forces now, as the recorder samples them.
  metrics::TrajectorySample sample() const;
  // As `imasim run --json`'s state_hash: 16 hex digits of the particles' positions.
  std::string state_hash() const;
  std::uint64_t steps() const { return runner_->steps_done(); }
  double dt() const { return double(session_->scene.patch.world.model.solver.dt); }
  // The endoscope's view, width x height x 3 bytes, drawn offscreen (EGL, Mesa's llvmpipe).
  std::vector<std::uint8_t> render(int width, int height) const;

  // Of the IMA's fat strands (the pedicle's), those the cautery divided (unit: 1).
  double pedicle_divided() const;

 private:
  scene::ThoraxSceneParams params_;
  haptics::ForceModelParams forces_;
  physics::Executor exec_;
  std::unique_ptr<session::SurgicalSession> session_;
  runner::CommandedInput input_;
  std::unique_ptr<runner::SessionRunner> runner_;
  std::unique_ptr<runner::InputStreamRecorder> recorder_;
};

int hand_index(const std::string& name);  // "forceps"/"left"/"0" -> 0, "hook"/"right"/"1" -> 1

}  // namespace imasim::python
