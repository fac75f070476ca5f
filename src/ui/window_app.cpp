#include "ui/window_app.hpp"

#include <epoxy/gl.h>
// After epoxy: GLFW must not pull in the system's GL header itself.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <thread>

#include "render/image_file.hpp"
#include "render/renderer.hpp"
#include "ui/frame_stats.hpp"
#include "ui/key_bindings.hpp"
#include "ui/panels.hpp"

namespace imasim::ui {

namespace {

using Clock = std::chrono::steady_clock;

std::string& glfw_error() {
  static std::string text;
  return text;
}

void on_glfw_error(int code, const char* description) {
  glfw_error() = std::string(description ? description : "unknown") + " (GLFW error " +
                 std::to_string(code) + ")";
}

constexpr float kRadiansPerPixel = 0.01f;  // orbit camera: drag to turn
constexpr float kDepthPixelsPerPixel = 1;  // Shift + right drag: vertical pixels to depth
constexpr int kMaxReportedGlErrors = 10;

// The drawing thread's whole state; GLFW's callbacks reach it through the window's user pointer.
class App {
 public:
  App(const WindowOptions& options, SimThread& sim, KeyboardMouseDevice* keyboard)
      : options_(options), sim_(sim), keyboard_(keyboard) {
    view_.orbit = options.orbit;
    view_.stereo = options.stereo;
  }
  ~App() { close(); }

  void open();
  WindowReport run();

  // GLFW callbacks (installed before ImGui's, which call them after their own).
  static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);
  static void on_mouse_button(GLFWwindow* w, int button, int action, int mods);
  static void on_cursor(GLFWwindow* w, double x, double y);
  static void on_scroll(GLFWwindow* w, double dx, double dy);
  static void on_focus(GLFWwindow* w, int focused);

 private:
  static App& of(GLFWwindow* w) { return *static_cast<App*>(glfwGetWindowUserPointer(w)); }
  void key(int key, int action);
  void command(Command c);
  bool over_view() const;
  void draw_scene(int width, int height);
  void check_gl_errors();
  void screenshot(int width, int height);
  void close();

  WindowOptions options_;
  SimThread& sim_;
  KeyboardMouseDevice* keyboard_;
  GLFWwindow* window_ = nullptr;
  bool imgui_glfw_ = false, imgui_gl_ = false, glfw_ = false;
  std::unique_ptr<render::Renderer> renderer_;
  ViewState view_;
  LiveNumbers numbers_;
  std::optional<ScoreCard> card_;
  std::uint64_t card_generation_ = 0;
  std::vector<Command> clicked_;
  bool quit_requested_ = false;
  double cursor_x_ = 0, cursor_y_ = 0;
  bool drag_view_ = false;  // a drag that began over the 3D view (not a panel)
  float view_aspect_ = 16.0f / 9.0f;
  WindowReport report_;
};

void App::open() {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) {
    throw WindowError("cannot open a window: " + glfw_error() +
                      (std::getenv("DISPLAY") ? "" : " ($DISPLAY is not set)"));
  }
  glfw_ = true;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
  window_ = glfwCreateWindow(options_.width, options_.height, "imasim: robotic IMA harvesting",
                             nullptr, nullptr);
  if (!window_) throw WindowError("cannot open an OpenGL 3.3 core window: " + glfw_error());
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(options_.vsync ? 1 : 0);
  if (epoxy_gl_version() < 33) throw WindowError("the display's OpenGL is older than 3.3 core");
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  report_.gl_renderer = renderer ? renderer : "unknown";
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, on_key);
  glfwSetMouseButtonCallback(window_, on_mouse_button);
  glfwSetCursorPosCallback(window_, on_cursor);
  glfwSetScrollCallback(window_, on_scroll);
  glfwSetWindowFocusCallback(window_, on_focus);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
  ImGui::StyleColorsDark();
  imgui_glfw_ = ImGui_ImplGlfw_InitForOpenGL(window_, true);
  imgui_gl_ = imgui_glfw_ && ImGui_ImplOpenGL3_Init("#version 330 core");
  if (!imgui_gl_) throw WindowError("Dear ImGui cannot start on this OpenGL context");
  try {
    renderer_ = std::make_unique<render::Renderer>();
  } catch (const std::exception& e) {
    throw WindowError(std::string("the renderer cannot start: ") + e.what());
  }
  check_gl_errors();  // set-up's own, if any, count too
}

void App::close() {
  renderer_.reset();  // its GL objects go while the context is current
  if (imgui_gl_) ImGui_ImplOpenGL3_Shutdown();
  if (imgui_glfw_) ImGui_ImplGlfw_Shutdown();
  if (imgui_glfw_ || imgui_gl_) ImGui::DestroyContext();
  imgui_gl_ = imgui_glfw_ = false;
  if (window_) glfwDestroyWindow(window_);
  window_ = nullptr;
  if (glfw_) glfwTerminate();
  glfw_ = false;
}

void App::on_key(GLFWwindow* w, int key, int, int action, int) {
  of(w).key(key, action);
}

void App::key(int key, int action) {
  if (action == GLFW_REPEAT) return;  // a held key is held; commands act once a press
  if (ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput) return;
  const KeyBinding* b = binding_for(key);
  if (!b) return;
  if (b->is_control) {
    if (keyboard_) keyboard_->set_held(b->control, action == GLFW_PRESS);
    return;
  }
  if (action == GLFW_PRESS) command(b->command);
}

void App::command(Command c) {
  switch (c) {
    case Command::none:
      return;
    case Command::quit:
      quit_requested_ = true;
      return;
    case Command::pause:
      sim_.set_paused(!sim_.paused());
      return;
    case Command::camera:
      view_.orbit = !view_.orbit;
      return;
    case Command::optics:
      sim_.set_optics(numbers_.optics_rad > Real(0.01) ? 0.0f : float(30 * std::numbers::pi / 180));
      return;
    case Command::stereo:
      view_.stereo = next_stereo(view_.stereo);
      return;
    case Command::restart:
      view_.show_score = false;
      sim_.restart();
      return;
    case Command::heart:
      sim_.set_beating(!numbers_.beating_next);
      view_.show_score = false;
      sim_.restart();
      return;
    case Command::record:
      sim_.set_recording(!numbers_.recording);
      return;
    case Command::end_session:
      sim_.end_session();
      return;
    case Command::help:
      view_.show_help = !view_.show_help;
      return;
    case Command::panels:
      view_.show_panels = !view_.show_panels;
      return;
    case Command::power_up:
    case Command::power_down:
      if (keyboard_) keyboard_->step_power(c == Command::power_up ? 1 : -1);
      return;
  }
}

bool App::over_view() const {
  return !(ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse);
}

void App::on_mouse_button(GLFWwindow* w, int, int action, int) {
  App& a = of(w);
  if (action == GLFW_PRESS) a.drag_view_ = a.over_view();
}

void App::on_cursor(GLFWwindow* w, double x, double y) {
  App& a = of(w);
  const auto dx = float(x - a.cursor_x_), dy = float(y - a.cursor_y_);
  a.cursor_x_ = x;
  a.cursor_y_ = y;
  if (!a.drag_view_) return;
  if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) {
    a.view_.orbit_camera.yaw -= kRadiansPerPixel * dx;
    a.view_.orbit_camera.pitch =
        std::clamp(a.view_.orbit_camera.pitch - kRadiansPerPixel * dy, -1.5f, 1.5f);
  }
  if (!a.keyboard_) return;
  const bool shift = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                     glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  const auto drag = [&](devices::Hand hand) {
    if (shift)
      a.keyboard_->add_drag(hand, 0, 0, -kDepthPixelsPerPixel * dy);
    else
      a.keyboard_->add_drag(hand, dx, dy, 0);
  };
  if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) drag(devices::Hand::right);
  if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS) drag(devices::Hand::left);
}

void App::on_scroll(GLFWwindow* w, double, double dy) {
  App& a = of(w);
  if (!a.over_view() || !std::isfinite(dy)) return;
  a.view_.orbit_camera.distance =
      std::clamp(a.view_.orbit_camera.distance * float(std::exp(-0.1 * dy)), 0.01f, 1.5f);
}

void App::on_focus(GLFWwindow* w, int focused) {
  // Keys released while another window had the focus never reach us: none stays held.
  App& a = of(w);
  if (!focused && a.keyboard_) a.keyboard_->release_all();
}

void App::draw_scene(int width, int height) {
  const render::RenderFrame* frame = sim_.latest_frame();
  const int view_width = view_.show_panels ? std::max(1, width - kPanelWidth) : width;
  if (!frame) {
    glViewport(0, 0, width, height);
    glClearColor(0.05f, 0.05f, 0.06f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    return;
  }
  if (!view_.orbit_placed) {
    view_.orbit_camera = render::default_orbit(*frame);
    view_.orbit_placed = true;
  }
  // One clear of the whole window for the view and the panels' column, which has the view's
  // background colour: a clear of a part of the window is drawn as a rectangle (renderer.hpp),
  // the view's cost 2-3 ms of the rasteriser's time a frame (docs/PERFORMANCE.md).
  const std::array<float, 3> background = render::background_colour(render::DrawMode::lit);
  glViewport(0, 0, width, height);
  glClearColor(background[0], background[1], background[2], 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const float eye_width =
      view_.stereo == render::StereoMode::side_by_side ? float(view_width) / 2 : float(view_width);
  view_aspect_ = eye_width / float(std::max(1, height));
  const render::Camera camera = view_.orbit ? render::orbit_camera(view_.orbit_camera, view_aspect_)
                                            : render::endoscope_camera(*frame, view_aspect_);
  render::draw_view(*renderer_, *frame, camera, view_.stereo, view_width, height, {}, 0, 0,
                    render::Clear::done_by_caller);
  // Hand the view to the rasteriser's threads now: they draw it while this thread builds the
  // panels. Left for the swap, the view and the panels went as one batch, and the window made
  // 36 frames a second instead of 48 (docs/PERFORMANCE.md).
  glFlush();
}

void App::check_gl_errors() {
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
    if (++report_.gl_errors <= kMaxReportedGlErrors) {
      std::fprintf(stderr, "imasim window: OpenGL error 0x%04x in frame %llu\n", unsigned(e),
                   static_cast<unsigned long long>(report_.frames));
    }
    if (report_.gl_errors > 1000) break;  // a lost context reports forever
  }
}

void App::screenshot(int width, int height) {
  render::RgbImage image;
  image.width = width;
  image.height = height;
  image.rgb.resize(std::size_t(width) * std::size_t(height) * 3);
  std::vector<std::uint8_t> rows(image.rgb.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
  check_gl_errors();
  const std::size_t stride = std::size_t(width) * 3;
  for (int y = 0; y < height; ++y)  // OpenGL's rows start at the bottom
    std::copy_n(rows.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * stride), stride,
                image.rgb.begin() + std::ptrdiff_t(std::size_t(y) * stride));
  try {
    render::write_png(options_.screenshot, image);
    report_.screenshot_written = true;
  } catch (const std::exception& e) {
    report_.screenshot_error = e.what();
  }
}

WindowReport App::run() {
  sim_.start();
  const Clock::time_point start = Clock::now();
  Clock::time_point last_frame = start;
  std::vector<double> periods;
  bool quit_key_sent = false;
  for (bool last = false; !last;) {
    const Clock::time_point frame_start = Clock::now();
    glfwPollEvents();
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    if (options_.quit_key_after_s >= 0 && !quit_key_sent && elapsed >= options_.quit_key_after_s) {
      quit_key_sent = true;
      // The same handler a real key press reaches (GLFW's key callback), press and release.
      on_key(window_, GLFW_KEY_ESCAPE, 0, GLFW_PRESS, 0);
      on_key(window_, GLFW_KEY_ESCAPE, 0, GLFW_RELEASE, 0);
    }
    sim_.latest_numbers(numbers_);
    if (const std::uint64_t g = sim_.score_card_generation(); g != card_generation_) {
      card_generation_ = g;
      card_ = sim_.score_card();
      view_.show_score = true;
    }
    if (quit_requested_) {
      report_.quit = "key";
      last = true;
    } else if (glfwWindowShouldClose(window_)) {
      report_.quit = "closed";
      last = true;
    } else if (options_.should_quit && options_.should_quit()) {
      report_.quit = "signal";
      last = true;
    } else if (options_.quit_when_finished && sim_.finished()) {
      report_.quit = "finished";
      last = true;
    }
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    if (width <= 0 || height <= 0) {  // minimised: nothing to draw
      if (last && !options_.screenshot.empty())
        report_.screenshot_error = "no screenshot: the window was minimised";
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    draw_scene(width, height);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    clicked_.clear();
    draw_panels(numbers_, card_, view_, width, height, clicked_);
    ImGui::Render();
    glViewport(0, 0, width, height);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    for (Command c : clicked_)
      command(c);
    check_gl_errors();
    if (last && !options_.screenshot.empty()) screenshot(width, height);
    glfwSwapBuffers(window_);
    ++report_.frames;
    const Clock::time_point now = Clock::now();
    if (std::chrono::duration<double>(now - start).count() > 1)
      periods.push_back(std::chrono::duration<double>(now - last_frame).count());
    last_frame = now;
    if (options_.max_fps > 0 && !last)
      std::this_thread::sleep_until(frame_start +
                                    std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>(1 / options_.max_fps)));
  }
  sim_.stop();
  const FrameStats s = frame_stats(periods);
  report_.median_fps = s.median_fps;
  report_.mean_fps = s.mean_fps;
  report_.p99_frame_ms = s.p99_frame_ms;
  return report_;
}

}  // namespace

void spread_software_rasteriser_threads() {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  ::setenv("LP_NUM_THREADS", std::to_string(cores + 1).c_str(), 0);
}

WindowReport run_window(const WindowOptions& options, SimThread& sim,
                        KeyboardMouseDevice* keyboard) {
  App app(options, sim, keyboard);
  app.open();  // throws WindowError; App's destructor closes what was opened
  return app.run();
}

}  // namespace imasim::ui
