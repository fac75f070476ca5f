// The offscreen renderer: the default scene drawn headless through EGL and Mesa's
// software rasteriser, checked against where its geometry projects and against a reference.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "physics/executor.hpp"
#include "render/camera.hpp"
#include "render/frame_of_session.hpp"
#include "render/image_file.hpp"
#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"
#include "render/stereo_view.hpp"
#include "scene/thorax_scene.hpp"
#include "session/surgical_session.hpp"

using namespace imasim;
using namespace imasim::render;

namespace {

constexpr int kWidth = 320, kHeight = 180;

// One session and one context for the suite: set-up is most of a test's time.
struct Fixture {
  session::SurgicalSession session =
      session::make_surgical_session(scene::default_thorax_scene_params(), {});
  OffscreenContext context{kWidth, kHeight};
  Renderer renderer;
  RenderFrame frame;
  Fixture() { frame_of_session(session, frame); }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

std::array<std::uint8_t, 3> pixel(const std::vector<std::uint8_t>& rgb, int x, int y) {
  const std::size_t i = (std::size_t(y) * kWidth + std::size_t(x)) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

// Distance from the eye along the view axis of a window depth (perspective depth undone).
float eye_distance(float window_depth, const Camera& c) {
  const float a = c.projection[10], b = c.projection[14];  // z_clip = a z + b, w = -z
  const float ndc = 2 * window_depth - 1;
  return b / (ndc + a);
}

struct Visibility {
  int visible = 0, matching = 0;
};

// For every vertex of the look's surfaces that projects inside the image and is not hidden
// behind other geometry (its distance within 0.5 mm of the depth buffer's), whether the key
// colour of its look is at its pixel (or a neighbour: a vertex on an outline).
Visibility check_look(Look look, const RenderFrame& frame, const Camera& camera,
                      const std::vector<std::uint8_t>& rgb, const std::vector<float>& depth) {
  Visibility v;
  const std::array<std::uint8_t, 3> key = key_colour(look);
  auto consider = [&](const std::array<float, 3>& p) {
    float x = 0, y = 0, d = 0;
    if (!project(camera, p, kWidth, kHeight, x, y, d)) return;
    const int px = int(x), py = int(y);
    if (px < 1 || py < 1 || px >= kWidth - 1 || py >= kHeight - 1 || d <= 0 || d >= 1) return;
    const float own = eye_distance(d, camera);
    const float drawn = eye_distance(depth[std::size_t(py) * kWidth + std::size_t(px)], camera);
    if (drawn < own - 0.0005f) return;  // something is in front
    ++v.visible;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (pixel(rgb, px + dx, py + dy) == key) {
          ++v.matching;
          return;
        }
  };
  for (const Surface& s : frame.surfaces) {
    if (s.look != look) continue;
    for (std::size_t i = 0; i + 2 < s.positions.size(); i += 3)
      consider({s.positions[i], s.positions[i + 1], s.positions[i + 2]});
  }
  if (look == Look::fat) {
    // A sphere's nearest point to the eye.
    for (std::size_t i = 0; i < frame.fat.count(); ++i) {
      std::array<float, 3> c{frame.fat.centres[3 * i], frame.fat.centres[3 * i + 1],
                             frame.fat.centres[3 * i + 2]};
      float n = 0;
      for (int k = 0; k < 3; ++k)
        n += (camera.eye[k] - c[k]) * (camera.eye[k] - c[k]);
      n = std::sqrt(n);
      for (int k = 0; k < 3; ++k)
        c[k] += frame.fat.radii[i] * (camera.eye[k] - c[k]) / n;
      consider(c);
    }
  }
  return v;
}

}  // namespace

TEST(OffscreenRender, TheDefaultSceneIsNotBlank) {
  Fixture& f = fixture();
  f.context.bind();
  const Camera camera = orbit_camera(default_orbit(f.frame), float(kWidth) / kHeight);
  f.renderer.draw(f.frame, camera, {0, 0, kWidth, kHeight});
  const std::vector<std::uint8_t> rgb = f.context.read_rgb();
  double mean = 0, mean2 = 0;
  std::map<int, int> colours;
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    const double l = (rgb[i] + rgb[i + 1] + rgb[i + 2]) / 3.0;
    mean += l, mean2 += l * l;
    ++colours[(rgb[i] >> 4) << 8 | (rgb[i + 1] >> 4) << 4 | (rgb[i + 2] >> 4)];
  }
  const double n = double(rgb.size() / 3);
  mean /= n, mean2 /= n;
  EXPECT_GT(std::sqrt(mean2 - mean * mean), 20.0) << "a flat image";
  EXPECT_GT(colours.size(), 50u) << "too few colours for lit tissue";
}

TEST(OffscreenRender, EachTissueAppearsWhereItsGeometryProjects) {
  Fixture& f = fixture();
  f.context.bind();
  const Camera camera = orbit_camera(default_orbit(f.frame), float(kWidth) / kHeight);
  f.renderer.draw(f.frame, camera, {0, 0, kWidth, kHeight}, DrawMode::look_colours);
  const std::vector<std::uint8_t> rgb = f.context.read_rgb();
  const std::vector<float> depth = f.context.read_depth();
  for (const Look look : {Look::fascia, Look::fat, Look::heart, Look::chest_wall, Look::bone}) {
    const Visibility v = check_look(look, f.frame, camera, rgb, depth);
    SCOPED_TRACE(look_name(look));
    EXPECT_GE(v.visible, 20) << "the default orbit should show it";
    EXPECT_GE(v.matching, int(0.95 * v.visible))
        << v.matching << " of " << v.visible << " visible points show the tissue's colour";
  }
  // The heart is a large part of this view, not a few stray pixels.
  int heart_pixels = 0;
  for (std::size_t i = 0; i < rgb.size(); i += 3)
    heart_pixels += rgb[i] == 0 && rgb[i + 1] == 0 && rgb[i + 2] == 255;
  EXPECT_GT(heart_pixels, kWidth * kHeight / 20);
}

TEST(OffscreenRender, TheEndoscopeShowsWhatItsOpticsLookAt) {
  // The scope 2 cm beyond its port (at the default 5 cm its lens is inside the heart of the
  // built-in scene: docs/rendering.md), with 0 and 30 degree optics.
  Fixture& f = fixture();
  for (const double optics_deg : {0.0, 30.0}) {
    SCOPED_TRACE(optics_deg);
    session::SurgicalSession s = f.session;
    session::SessionInput input;
    input.camera.optics = Real(optics_deg * M_PI / 180);
    input.camera.insertion = Real(0.02);
    physics::Executor exec(1);
    ASSERT_TRUE(session::step_session(s, input, exec).ok());
    RenderFrame frame;
    frame_of_session(s, frame);
    const Camera camera = endoscope_camera(frame, float(kWidth) / kHeight);
    // The picture's centre is the optics' view direction; 30 degrees off the shaft with 30
    // degree optics.
    const Vec3 ahead = s.camera.eye + 0.05 * s.camera.view_direction;
    float x = 0, y = 0, d = 0;
    ASSERT_TRUE(project(camera, {float(ahead.x()), float(ahead.y()), float(ahead.z())}, kWidth,
                        kHeight, x, y, d));
    EXPECT_NEAR(x, kWidth / 2.0, 0.01);
    EXPECT_NEAR(y, kHeight / 2.0, 0.01);
    EXPECT_NEAR(std::acos(s.camera.view_direction.dot(s.camera.shaft)) * 180 / M_PI, optics_deg,
                1e-6);
    f.context.bind();
    f.renderer.draw(frame, camera, {0, 0, kWidth, kHeight}, DrawMode::look_colours);
    const std::vector<std::uint8_t> rgb = f.context.read_rgb();
    const std::vector<float> depth = f.context.read_depth();
    for (const Look look : {Look::heart, Look::bone}) {
      SCOPED_TRACE(look_name(look));
      const Visibility v = check_look(look, frame, camera, rgb, depth);
      EXPECT_GE(v.visible, 10);
      EXPECT_GE(v.matching, int(0.95 * v.visible)) << v.matching << " of " << v.visible;
    }
  }
}

TEST(OffscreenRender, MatchesTheReferenceImage) {
  Fixture& f = fixture();
  f.context.bind();
  const Camera camera = orbit_camera(default_orbit(f.frame), float(kWidth) / kHeight);
  f.renderer.draw(f.frame, camera, {0, 0, kWidth, kHeight});
  const RgbImage drawn{kWidth, kHeight, f.context.read_rgb()};
  // Kept for a look when the comparison fails (and to make a new reference on purpose).
  write_png(testing::TempDir() + "imasim_render_drawn.png", drawn);
  const std::string reference_path =
      std::string(IMASIM_SOURCE_DIR) + "/tests/data/render/default_orbit.png";
  const RgbImage reference = read_png(reference_path);
  ASSERT_EQ(reference.width, kWidth);
  ASSERT_EQ(reference.height, kHeight);
  double total = 0;
  int far_off = 0;
  for (std::size_t i = 0; i < drawn.rgb.size(); ++i) {
    const int d = std::abs(int(drawn.rgb[i]) - int(reference.rgb[i]));
    total += d;
    far_off += d > 24;
  }
  const double mean = total / double(drawn.rgb.size());
  // Tolerances for another rasteriser build or CPU (llvmpipe's vector width), not for a change.
  EXPECT_LE(mean, 1.0) << "mean difference per channel (0-255); drawn image in "
                       << testing::TempDir();
  EXPECT_LE(far_off, int(drawn.rgb.size() / 100));
}

TEST(OffscreenRender, CoagulatedTissueIsDrawnDarker) {
  Fixture& f = fixture();
  RenderFrame frame = f.frame;
  f.context.bind();
  const Camera camera = orbit_camera(default_orbit(frame), float(kWidth) / kHeight);
  f.renderer.draw(frame, camera, {0, 0, kWidth, kHeight});
  const std::vector<std::uint8_t> before = f.context.read_rgb();
  for (Surface& s : frame.surfaces)
    if (s.look == Look::fascia) std::fill(s.shade.begin(), s.shade.end(), 1.0f);
  f.renderer.draw(frame, camera, {0, 0, kWidth, kHeight});
  const std::vector<std::uint8_t> after = f.context.read_rgb();
  long sum_before = 0, sum_after = 0;
  for (std::size_t i = 0; i < before.size(); ++i)
    sum_before += before[i], sum_after += after[i];
  EXPECT_LT(double(sum_after), 0.97 * double(sum_before));
}

namespace {

// A lone fat sphere 5 cm from the eye, its centre in the direction (tan_x, tan_y, -1) of the
// camera: the pixels drawn in its key colour against the pixels whose centre's ray meets it.
struct SphereCoverage {
  int drawn = 0, expected = 0, drawn_not_expected = 0, expected_not_drawn = 0;
};

SphereCoverage lone_sphere_coverage(float tan_x, float tan_y, float distance = 0.05f) {
  Fixture& f = fixture();
  f.context.bind();
  Camera camera;
  camera.projection = orbit_camera(OrbitCamera{}, float(kWidth) / kHeight).projection;
  for (int k = 0; k < 4; ++k)
    camera.view[std::size_t(5 * k)] = 1;  // the eye at the origin, looking along -z
  const float radius = 0.003f;
  const float norm = std::sqrt(tan_x * tan_x + tan_y * tan_y + 1);
  const std::array<float, 3> c{distance * tan_x / norm, distance * tan_y / norm, -distance / norm};
  RenderFrame frame;
  frame.fat.centres.assign(c.begin(), c.end());
  frame.fat.radii = {radius};
  f.renderer.draw(frame, camera, {0, 0, kWidth, kHeight}, DrawMode::look_colours);
  const std::vector<std::uint8_t> rgb = f.context.read_rgb();
  SphereCoverage coverage;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      // The ray through the pixel's centre (y down from the top, as read_rgb gives rows).
      const double dx = (2 * (x + 0.5) / kWidth - 1) / camera.projection[0];
      const double dy = (1 - 2 * (y + 0.5) / kHeight) / camera.projection[5];
      const double dn = std::sqrt(dx * dx + dy * dy + 1);
      const double along = (dx * c[0] + dy * c[1] - c[2]) / dn;  // ray . centre
      const double c2 = double(c[0]) * c[0] + double(c[1]) * c[1] + double(c[2]) * c[2];
      const bool hit = along > 0 && c2 - along * along <= double(radius) * radius;
      const bool drawn = pixel(rgb, x, y) == key_colour(Look::fat);
      coverage.expected += hit;
      coverage.drawn += drawn;
      coverage.drawn_not_expected += drawn && !hit;
      coverage.expected_not_drawn += hit && !drawn;
    }
  }
  return coverage;
}

}  // namespace

// The impostor's rectangle bounds the sphere's whole outline: off the view axis the outline is
// an ellipse longer by about 1 / cos(angle), which a square sized for the axis cut off.
TEST(OffscreenRender, ASphereImpostorCoversItsWholeOutlineOnAndOffTheAxis) {
  const float half_width = 1 / orbit_camera(OrbitCamera{}, float(kWidth) / kHeight).projection[0];
  const float half_height = std::tan(OrbitCamera{}.vertical_fov / 2);
  // The last two centres lie just outside the image (right, then top): a part of the sphere is
  // still in view and must be drawn.
  for (const auto& [tx, ty] :
       {std::pair{0.0f, 0.0f}, std::pair{0.8f * half_width, 0.0f},
        std::pair{0.85f * half_width, -0.8f * half_height}, std::pair{half_width + 0.02f, 0.0f},
        std::pair{0.3f * half_width, half_height + 0.02f}}) {
    SCOPED_TRACE("direction tan " + std::to_string(tx) + ", " + std::to_string(ty));
    const SphereCoverage c = lone_sphere_coverage(tx, ty);
    ASSERT_GT(c.expected, 100) << "the sphere should cover a few hundred pixels";
    // The shader casts the same ray through each pixel's centre: only the float rounding of a
    // pixel right on the outline may differ. (A square of 1.1 radii lost 4-5 % off the axis.)
    EXPECT_NEAR(c.drawn, c.expected, 0.01 * c.expected);
    EXPECT_LE(c.drawn_not_expected, int(0.01 * c.expected));
    // Not a pixel of the outline is cut off: a sprite 3 % too small loses a sliver at each of
    // the square's four tangent points, 6 pixels off the axis here, within the 1 % above.
    EXPECT_LE(c.expected_not_drawn, 1);
  }
  // 5 mm from the eye the sphere needs a sprite wider than the rasteriser's points (255 pixels
  // on llvmpipe): it is drawn as a rectangle, on and off the axis.
  for (const auto& [tx, ty] : {std::pair{0.0f, 0.0f}, std::pair{0.5f * half_width, 0.0f}}) {
    SCOPED_TRACE("near, direction tan " + std::to_string(tx) + ", " + std::to_string(ty));
    const SphereCoverage c = lone_sphere_coverage(tx, ty, 0.005f);
    ASSERT_GT(c.expected, 15000) << "the sphere should fill most of the image";
    EXPECT_NEAR(c.drawn, c.expected, 0.01 * c.expected);
    EXPECT_LE(c.drawn_not_expected, int(0.01 * c.expected));
  }
}

TEST(Stereo, APointAtTheConvergenceDistanceCoincidesInBothEyes) {
  Fixture& f = fixture();
  const Camera centre = orbit_camera(default_orbit(f.frame), 16.0f / 9.0f);
  const float separation = 0.004f, convergence = 0.1f;
  const Camera left = stereo_eye(centre, -1, separation, convergence);
  const Camera right = stereo_eye(centre, +1, separation, convergence);
  // The eyes are `separation` apart.
  float d2 = 0;
  for (int k = 0; k < 3; ++k)
    d2 += (left.eye[k] - right.eye[k]) * (left.eye[k] - right.eye[k]);
  EXPECT_NEAR(std::sqrt(d2), separation, 1e-6);
  // A point on the centre's axis at the convergence distance: same pixel in both eyes; a nearer
  // one: crossed (left eye sees it further right).
  const float* v = centre.view.data();
  const std::array<float, 3> forward{-v[2], -v[6], -v[10]};
  auto at = [&](float distance) {
    return std::array<float, 3>{centre.eye[0] + distance * forward[0],
                                centre.eye[1] + distance * forward[1],
                                centre.eye[2] + distance * forward[2]};
  };
  float xl = 0, yl = 0, dl = 0, xr = 0, yr = 0, dr = 0;
  ASSERT_TRUE(project(left, at(convergence), 1280, 720, xl, yl, dl));
  ASSERT_TRUE(project(right, at(convergence), 1280, 720, xr, yr, dr));
  EXPECT_NEAR(xl, xr, 0.01);
  EXPECT_NEAR(xl, 640, 0.01);
  EXPECT_NEAR(yl, yr, 1e-3);
  ASSERT_TRUE(project(left, at(0.5f * convergence), 1280, 720, xl, yl, dl));
  ASSERT_TRUE(project(right, at(0.5f * convergence), 1280, 720, xr, yr, dr));
  EXPECT_GT(xl - xr, 5.0f);
}

TEST(Stereo, SideBySideDrawsOneEyeInEachHalf) {
  Fixture& f = fixture();
  f.context.bind();
  const Camera camera =
      orbit_camera(default_orbit(f.frame), stereo_aspect("side-by-side", kWidth, kHeight));
  draw_view(f.renderer, f.frame, camera, StereoMode::side_by_side, kWidth, kHeight, {0.01f, 0.1f});
  const std::vector<std::uint8_t> rgb = f.context.read_rgb();
  long left = 0, right = 0, differ = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth / 2; ++x) {
      const auto a = pixel(rgb, x, y), b = pixel(rgb, x + kWidth / 2, y);
      left += a[0] + a[1] + a[2], right += b[0] + b[1] + b[2];
      differ += a != b;
    }
  EXPECT_GT(left, 0);
  EXPECT_GT(right, 0);
  EXPECT_GT(differ, 100) << "the two eyes see the same image";
  EXPECT_LT(std::abs(double(left - right)), 0.2 * double(left)) << "one eye is mostly empty";
}

TEST(Stereo, AnaglyphPutsTheLeftEyeInRedAndTheRightInCyan) {
  Fixture& f = fixture();
  f.context.bind();
  const Camera camera = orbit_camera(default_orbit(f.frame), float(kWidth) / kHeight);
  const StereoParams stereo{0.01f, 0.1f};
  draw_view(f.renderer, f.frame, camera, StereoMode::anaglyph, kWidth, kHeight, stereo);
  const std::vector<std::uint8_t> anaglyph = f.context.read_rgb();
  f.renderer.draw(f.frame, stereo_eye(camera, -1, stereo.separation, stereo.convergence),
                  {0, 0, kWidth, kHeight});
  const std::vector<std::uint8_t> left = f.context.read_rgb();
  f.renderer.draw(f.frame, stereo_eye(camera, +1, stereo.separation, stereo.convergence),
                  {0, 0, kWidth, kHeight});
  const std::vector<std::uint8_t> right = f.context.read_rgb();
  for (std::size_t i = 0; i < anaglyph.size(); i += 3) {
    ASSERT_EQ(anaglyph[i], left[i]) << "red from the left eye, pixel " << i / 3;
    ASSERT_EQ(anaglyph[i + 1], right[i + 1]) << "green from the right eye, pixel " << i / 3;
    ASSERT_EQ(anaglyph[i + 2], right[i + 2]) << "blue from the right eye, pixel " << i / 3;
  }
}

TEST(OffscreenRender, FramesFollowTheSession) {
  // After steps with the forceps moved, the frame's instrument surface moved with them.
  Fixture& f = fixture();
  session::SurgicalSession s = f.session;
  RenderFrame before;
  frame_of_session(s, before);
  physics::Executor exec(1);
  session::SessionInput input;
  Pose target = s.stations[0].pose;
  target.translation += Vec3(0, -0.004, 0.0);
  input.left.source = surgery::PoseSource::tool;
  input.left.pose = target;
  for (int k = 0; k < 100; ++k)
    ASSERT_TRUE(session::step_session(s, input, exec).ok());
  RenderFrame after;
  frame_of_session(s, after);
  ASSERT_EQ(before.surfaces.size(), after.surfaces.size());
  double moved = 0;
  for (std::size_t i = 0; i < after.surfaces.size(); ++i) {
    if (after.surfaces[i].look != Look::instrument) continue;
    ASSERT_EQ(before.surfaces[i].positions.size(), after.surfaces[i].positions.size());
    for (std::size_t k = 0; k < after.surfaces[i].positions.size(); ++k)
      moved = std::max(moved, double(std::abs(after.surfaces[i].positions[k] -
                                              before.surfaces[i].positions[k])));
  }
  EXPECT_GT(moved, 0.002);
  EXPECT_NEAR(after.time_s, 100 * s.scene.patch.world.model.solver.dt, 1e-12);
}
