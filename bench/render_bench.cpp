// The renderer on Mesa's software rasteriser (llvmpipe, no GPU), offscreen at the window's size:
// the frame copied from the session, drawn and finished (glFinish: the rasteriser's threads
// done), per mode, from the default orbit camera or the endoscope's. Frames per second = 1000 / ms.
#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <atomic>
#include <chrono>
#include <thread>

#include <optional>

#include "physics/executor.hpp"
#include "render/camera.hpp"
#include "render/frame_of_session.hpp"
#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"
#include "render/stereo_view.hpp"
#include "scene/thorax_scene.hpp"
#include "session/surgical_session.hpp"

namespace {

using namespace imasim;

// The physics as the window runs it, on its own thread: the default session stepped in real time
// (one 5 ms step every 5 ms of wall-clock time, with the example script's inputs).
class RealTimePhysics {
 public:
  RealTimePhysics()
      : session_(session::make_surgical_session(scene::default_thorax_scene_params(), {})),
        thread_([this] { run(); }) {}
  ~RealTimePhysics() {
    stop_ = true;
    thread_.join();
  }
  std::uint64_t late_steps() const { return late_; }

 private:
  void run() {
    physics::Executor exec(1);
    const double dt = session_.scene.patch.world.model.solver.dt;
    auto next = std::chrono::steady_clock::now();
    while (!stop_) {
      session::step_session(session_, {}, exec);
      next += std::chrono::microseconds(std::int64_t(dt * 1e6));
      if (std::chrono::steady_clock::now() > next) ++late_;
      std::this_thread::sleep_until(next);
    }
  }
  session::SurgicalSession session_;
  std::atomic<bool> stop_{false};
  std::uint64_t late_ = 0;
  std::thread thread_;
};

void BM_RenderFrame(benchmark::State& state) {
  const int width = int(state.range(0)), height = int(state.range(1));
  const auto mode = static_cast<render::StereoMode>(state.range(2));
  std::optional<RealTimePhysics> physics;
  if (state.range(3) != 0) physics.emplace();
  session::SurgicalSession session =
      session::make_surgical_session(scene::default_thorax_scene_params(), {});
  render::OffscreenContext context(width, height);
  render::Renderer renderer;
  render::RenderFrame frame;
  render::frame_of_session(session, frame);
  const float aspect =
      float(width) / float(height) / (mode == render::StereoMode::side_by_side ? 2.0f : 1.0f);
  const render::Camera camera = state.range(4) != 0
                                    ? render::endoscope_camera(frame, aspect)
                                    : render::orbit_camera(render::default_orbit(frame), aspect);
  for (auto _ : state) {
    render::frame_of_session(session, frame);
    context.bind();
    render::draw_view(renderer, frame, camera, mode, width, height);
    glFinish();
  }
  state.counters["fps"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
  if (physics) state.counters["late_steps"] = double(physics->late_steps());
}
BENCHMARK(BM_RenderFrame)
    ->ArgNames({"w", "h", "stereo", "physics", "endoscope"})
    ->Args({1280, 720, 0, 0, 0})
    ->Args({1280, 720, 1, 0, 0})
    ->Args({1280, 720, 2, 0, 0})
    ->Args({1280, 720, 0, 1, 0})
    ->Args({1280, 720, 0, 0, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
