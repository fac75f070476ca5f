// Heat maps as in Fig. 13 (metrics/heat_map.hpp, metrics/heat_map_frame.hpp,
// console/heat_map_frame_of.hpp): projection onto a known plane, the kernel density against its
// closed form, the PNG read back pixel by pixel, the frame file round trip and its refusals, and
// the frame of the built-in session.
#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>

#include "console/heat_map_frame_of.hpp"
#include "metrics/colour_map.hpp"
#include "metrics/heat_map.hpp"
#include "metrics/output_file.hpp"
#include "session/surgical_session.hpp"

namespace {

using namespace imasim;
using metrics::HeatMapFrame;
using metrics::PlanePoint;

const std::string kDir = ::testing::TempDir();

// A plane through (0.1, 0.2, 0.3) with u = z and v = -x (normal -y).
HeatMapFrame tilted_frame() {
  HeatMapFrame f;
  f.origin = Vec3(0.1, 0.2, 0.3);
  f.u = Vec3::UnitZ();
  f.v = -Vec3::UnitX();
  return f;
}

// In the plane z = 0 (u = x, v = y): the centerline along u, a fascia rectangle, a fat triangle.
HeatMapFrame flat_frame() {
  HeatMapFrame f;
  f.centerline = {Vec3(-0.04, 0, 0), Vec3(0, 0, 0), Vec3(0.04, 0, 0)};
  f.outlines.push_back(
      {"fascia",
       {0.15, 0.35, 0.80},
       {Vec3(-0.04, -0.02, 0), Vec3(0.04, -0.02, 0), Vec3(0.04, 0.02, 0), Vec3(-0.04, 0.02, 0)},
       true});
  f.outlines.push_back({"fat",
                        {0.2, 0.58, 0.18},
                        {Vec3(-0.03, -0.03, 0), Vec3(0.03, -0.03, 0), Vec3(0, 0.025, 0)},
                        true});
  return f;
}

struct Picture {
  int width = 0, height = 0;
  std::vector<std::array<int, 3>> rgb;  // row-major, 0-255
  std::array<int, 3> at(double x, double y) const {
    return rgb[std::size_t(int(y)) * std::size_t(width) + std::size_t(int(x))];
  }
};

Picture read_png(const std::string& path) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  Picture p;
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
    p.width = cairo_image_surface_get_width(s);
    p.height = cairo_image_surface_get_height(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    for (int y = 0; y < p.height; ++y)
      for (int x = 0; x < p.width; ++x) {
        std::uint32_t px;
        std::memcpy(&px, data + std::ptrdiff_t(y) * stride + 4 * x, 4);
        p.rgb.push_back({int((px >> 16) & 255), int((px >> 8) & 255), int(px & 255)});
      }
  }
  cairo_surface_destroy(s);
  return p;
}

std::array<int, 3> bytes(const std::array<double, 3>& c) {
  return {int(std::lround(255 * c[0])), int(std::lround(255 * c[1])), int(std::lround(255 * c[2]))};
}

void expect_colour(const std::array<int, 3>& got, const std::array<int, 3>& want, int tolerance,
                   const char* what) {
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(got[k], want[k], tolerance)
        << what << ": got " << got[0] << "," << got[1] << "," << got[2] << " want " << want[0]
        << "," << want[1] << "," << want[2];
}

TEST(HeatMapFrame, ProjectsOrthogonallyOntoAKnownPlane) {
  const HeatMapFrame f = tilted_frame();
  // 10 mm along u, 20 mm along v, 0.5 m off the plane along its normal (-y): the offset drops out.
  const Vec3 p = f.origin + 0.01 * f.u + 0.02 * f.v + 0.5 * Vec3(0, -1, 0);
  const PlanePoint q = metrics::project(f, p);
  EXPECT_NEAR(q.x(), 0.01, 1e-15);
  EXPECT_NEAR(q.y(), 0.02, 1e-15);
  const Vec3 points[] = {f.origin, Vec3(0.1, 0.2, 0.35), Vec3(0.05, 0.9, 0.3)};
  const std::vector<PlanePoint> all = metrics::project(f, points);
  EXPECT_NEAR(all[0].norm(), 0, 1e-15);
  EXPECT_NEAR(all[1].x(), 0.05, 1e-15);
  EXPECT_NEAR(all[2].y(), 0.05, 1e-15);  // x = 0.05 is 0.05 m along v = -x from the origin
}

TEST(HeatMapDensity, EqualsTheClosedFormGaussianSumAtPixels) {
  const HeatMapFrame f = flat_frame();
  const std::vector<Vec3> points = {Vec3(0.01, 0.005, 0), Vec3(0.0105, 0.0062, 0.3),
                                    Vec3(-0.02, -0.01, -0.1), Vec3(0.012, 0.004, 0)};
  metrics::HeatMapStyle style;
  style.bandwidth = 0.0015;
  const metrics::DensityGrid g = metrics::heat_map_density(f, points, style);
  ASSERT_EQ(g.density.size(), std::size_t(g.view.width) * std::size_t(g.view.height));
  const double h = style.bandwidth;
  auto closed_form = [&](const PlanePoint& x) {
    double sum = 0;
    for (const Vec3& p : points) {
      const PlanePoint d = x - metrics::project(f, p);
      sum += std::exp(-d.squaredNorm() / (2 * h * h)) / (2 * std::numbers::pi * h * h);
    }
    return sum / double(points.size()) * 1e-6;  // per mm^2
  };
  const auto [cx, cy] = g.view.to_picture({0.0105, 0.0055});
  const int col = int(cx) - g.view.left, row = int(cy) - g.view.top;
  for (const auto& [dc, dr] : std::vector<std::pair<int, int>>{{0, 0}, {3, -2}, {-7, 5}, {12, 0}}) {
    const double want = closed_form(g.view.pixel_centre(col + dc, row + dr));
    EXPECT_GT(want, 1e-3);
    EXPECT_NEAR(g.at(col + dc, row + dr), want, 1e-5 * g.max) << dc << "," << dr;
  }
  // Share of samples per mm^2: summed over the pixels (all mass is inside the view) it is 1.
  double total = 0;
  for (double d : g.density)
    total += d;
  const double pixel_mm2 = std::pow(1000 * g.view.metres_per_pixel, 2);
  EXPECT_NEAR(total * pixel_mm2, 1.0, 1e-3);
  // Far from every sample (more than 5 bandwidths) the density is exactly zero.
  const auto [fx, fy] = g.view.to_picture({0.035, -0.025});
  EXPECT_EQ(g.at(int(fx) - g.view.left, int(fy) - g.view.top), 0.0);
  // Equal scale: as many pixels to the metre on both axes; the view holds every outline.
  const auto [x0, y0] = g.view.to_picture({-0.04, 0.0});
  const auto [x1, y1] = g.view.to_picture({0.0, 0.04});
  EXPECT_NEAR(x1 - x0, y0 - y1, 1e-9);
  const auto [left, top] = g.view.to_picture({-0.04, 0.025});
  const auto [right, bottom] = g.view.to_picture({0.04, -0.03});
  EXPECT_GT(left, g.view.left);
  EXPECT_GT(top, g.view.top);
  EXPECT_LT(right, g.view.left + g.view.width);
  EXPECT_LT(bottom, g.view.top + g.view.height);
}

TEST(HeatMapPng, ClusterIsHotCenterlineIsRedFarIsBackground) {
  HeatMapFrame f = flat_frame();
  std::vector<Vec3> points(300, Vec3(0.015, 0.012, 0));  // a dense cluster
  for (int k = 0; k < 40; ++k)                           // and a sparse trail
    points.push_back(Vec3(-0.03 + 0.0015 * k, -0.012, 0));
  metrics::HeatMapStyle style;
  style.subtitle = "SAI = 0.583";
  const std::string png = kDir + "imasim_heat_map_test.png";
  const metrics::DensityGrid g = metrics::write_heat_map_png(f, points, style, png);
  const Picture pic = read_png(png);
  ASSERT_EQ(pic.width, style.width);
  ASSERT_EQ(pic.height, style.height);
  const auto [hx, hy] = g.view.to_picture({0.015, 0.012});
  expect_colour(pic.at(hx, hy), bytes(metrics::heat_colour(1.0)), 6, "the cluster");
  const auto [lx, ly] = g.view.to_picture({-0.025, 0.0});
  expect_colour(pic.at(lx, ly), bytes(metrics::kCenterlineRgb), 3, "the centerline");
  const auto [bx, by] = g.view.to_picture({-0.035, 0.027});  // beyond the outlines and samples
  expect_colour(pic.at(bx, by), bytes(metrics::kHeatMapBackgroundRgb), 1, "the background");
  const auto [ox, oy] = g.view.to_picture({-0.04, 0.01});  // on the fascia's left edge
  expect_colour(pic.at(ox, oy), bytes(f.outlines[0].rgb), 12, "the fascia outline");
  // The figure outside the plot area is white (the title band's empty right part).
  expect_colour(pic.at(style.width - 30, 10), {255, 255, 255}, 0, "the margin");
}

TEST(HeatMapPng, ErrorsNameThePath) {
  const std::string png = kDir + "no_such_directory/x.png";
  try {
    metrics::write_heat_map_png(flat_frame(), {}, {}, png);
    FAIL() << "wrote into a missing directory";
  } catch (const metrics::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(png), std::string::npos) << e.what();
  }
  metrics::HeatMapStyle tiny;
  tiny.width = 100;
  EXPECT_THROW(metrics::write_heat_map_png(flat_frame(), {}, tiny, kDir + "t.png"),
               std::invalid_argument);
  const Vec3 bad[] = {Vec3(NAN, 0, 0)};
  EXPECT_THROW(metrics::heat_map_density(flat_frame(), bad, {}), std::invalid_argument);
}

TEST(HeatMapFrameFile, RoundTripsExactly) {
  HeatMapFrame f = flat_frame();
  f.origin = Vec3(0.1234567890123, -0.5, 1e-7);
  const double c = std::cos(0.3), s = std::sin(0.3);
  f.u = Vec3(c, s, 0);
  f.v = Vec3(-s, c, 0);
  f.outlines[1].closed = false;
  const std::string path = kDir + "imasim_frame_roundtrip.json";
  metrics::write_heat_map_frame(f, path);
  const HeatMapFrame r = metrics::read_heat_map_frame(path);
  EXPECT_EQ(r.origin, f.origin);
  EXPECT_EQ(r.u, f.u);
  EXPECT_EQ(r.v, f.v);
  EXPECT_EQ(r.centerline, f.centerline);
  ASSERT_EQ(r.outlines.size(), 2u);
  EXPECT_EQ(r.outlines[1].name, "fat");
  EXPECT_EQ(r.outlines[1].rgb, f.outlines[1].rgb);
  EXPECT_EQ(r.outlines[1].points, f.outlines[1].points);
  EXPECT_FALSE(r.outlines[1].closed);
  EXPECT_TRUE(r.outlines[0].closed);
}

// The frame's text with one substitution, parsed; the error message.
std::string refusal(const std::string& from, const std::string& to) {
  std::string text = metrics::heat_map_frame_json(flat_frame());
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  try {
    metrics::parse_heat_map_frame(text, "f.json");
  } catch (const metrics::HeatMapFrameError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(HeatMapFrameFile, MalformedFramesAreRefusedNamingTheKey) {
  EXPECT_EQ(refusal("\"u\":", "\"w\":"), "f.json: key 'u': missing");
  EXPECT_NE(refusal("\"u\": [\n  1.0,", "\"u\": [\n  2.0,").find("key 'u': not of unit length"),
            std::string::npos);
  EXPECT_NE(refusal("\"v\": [\n  0.0,\n  1.0,", "\"v\": [\n  0.6,\n  0.8,")
                .find("key 'v': not perpendicular to u"),
            std::string::npos);
  EXPECT_NE(refusal("0.15,", "1.5,").find("f.json: key 'outlines[0].rgb'"), std::string::npos);
  EXPECT_NE(refusal("\"closed\": true", "\"closed\": 1").find("key 'outlines[0].closed'"),
            std::string::npos);
  EXPECT_NE(refusal("\"name\": \"fat\"", "\"name\": 7").find("key 'outlines[1].name'"),
            std::string::npos);
  EXPECT_NE(refusal("\"centerline\": [\n  [\n   -0.04", "\"centerline\": [\n  [\n   \"x\"")
                .find("key 'centerline[0]'"),
            std::string::npos);
  EXPECT_NE(refusal("\"format\": \"imasim heat map frame\"", "\"format\": \"other\"")
                .find("key 'format'"),
            std::string::npos);
  // Not JSON: the line is named.
  const std::string broken = metrics::heat_map_frame_json(flat_frame()) + "}";
  try {
    metrics::parse_heat_map_frame(broken, "f.json");
    FAIL();
  } catch (const metrics::HeatMapFrameError& e) {
    EXPECT_NE(std::string(e.what()).find("f.json:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not JSON"), std::string::npos) << e.what();
  }
  EXPECT_THROW(metrics::read_heat_map_frame(kDir + "no_such_frame.json"),
               metrics::HeatMapFrameError);
}

TEST(HeatMapFrameOf, ConvexHullAndBoundaryLoop) {
  const std::vector<PlanePoint> hull = console::convex_hull(
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {0.5, 0}, {0.2, 0.7}, {1, 1}});
  ASSERT_EQ(hull.size(), 4u);  // the corners only: interior, edge and repeated points dropped
  double area = 0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const PlanePoint& a = hull[i];
    const PlanePoint& b = hull[(i + 1) % hull.size()];
    area += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_NEAR(area / 2, 1.0, 1e-15);  // counter-clockwise, the unit square
  // A 2 x 2 grid of quads (vertices 0..8, row-major): the rim has 8 vertices, the centre (4) is
  // not on it.
  std::vector<geometry::Triangle> grid;
  for (std::uint32_t r = 0; r < 2; ++r)
    for (std::uint32_t c = 0; c < 2; ++c) {
      const std::uint32_t a = r * 3 + c;
      grid.push_back({a, a + 1, a + 4});
      grid.push_back({a, a + 4, a + 3});
    }
  const std::vector<std::uint32_t> loop = console::longest_boundary_loop(grid);
  EXPECT_EQ(loop.size(), 8u);
  EXPECT_EQ(std::count(loop.begin(), loop.end(), 4u), 0);
}

TEST(HeatMapFrameOf, TheBuiltInSessionLiesInTheChestWallsPlane) {
  const session::SurgicalSession s =
      session::make_surgical_session(scene::default_thorax_scene_params(), {});
  const HeatMapFrame f = console::heat_map_frame_of(s);
  EXPECT_NEAR(f.u.norm(), 1, 1e-12);
  EXPECT_NEAR(f.v.norm(), 1, 1e-12);
  EXPECT_NEAR(f.u.dot(f.v), 0, 1e-12);
  EXPECT_GT(f.u.z(), 0.99);  // along the IMA, cranial to caudal
  EXPECT_GT(f.v.x(), 0.9);   // across it, laterally
  ASSERT_EQ(f.outlines.size(), 3u);
  EXPECT_EQ(f.outlines[0].name, "fascia");
  EXPECT_EQ(f.outlines[1].name, "fat");
  EXPECT_EQ(f.outlines[2].name, "heart");
  // The fascia is the anatomy's 40 mm x 150 mm rectangle, parallel to the plane (its area and
  // perimeter projected whole), turned in it by the IMA's lateral drift.
  const std::vector<PlanePoint> fascia = metrics::project(f, f.outlines[0].points);
  double area = 0, perimeter = 0;
  for (std::size_t i = 0; i < fascia.size(); ++i) {
    const PlanePoint& p = fascia[i];
    const PlanePoint& q = fascia[(i + 1) % fascia.size()];
    area += (p.x() * q.y() - p.y() * q.x()) / 2;
    perimeter += (q - p).norm();
  }
  const scene::AnatomyParams& a = s.scene.patient;
  EXPECT_NEAR(std::abs(area), a.fascia_length * a.fascia_width, 1e-9);
  EXPECT_NEAR(perimeter, 2 * (a.fascia_length + a.fascia_width), 1e-9);
  // The IMA's midpoint is the origin; the centerline runs along u.
  const PlanePoint first = metrics::project(f, f.centerline.front());
  const PlanePoint last = metrics::project(f, f.centerline.back());
  EXPECT_NEAR(last.x() - first.x(), a.ima_course_length, 2e-3);
  EXPECT_LT(std::abs(first.y()) + std::abs(last.y()), a.ima_lateral_drift + 1e-3);
}

}  // namespace
