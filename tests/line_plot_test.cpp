// The small plotting module (metrics/line_plot.hpp, metrics/plot_ticks.hpp): nice ticks, and the
// PNG read back with cairo: each series' colour where its points lie, bars side by side, the
// reference line, refusals.
#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "metrics/line_plot.hpp"
#include "metrics/output_file.hpp"
#include "metrics/plot_ticks.hpp"

namespace {

using namespace imasim::metrics;

const std::string kDir = ::testing::TempDir();

// The pixel at (x, y) of a PNG, 0-255 per channel, or {-1, -1, -1}.
std::array<int, 3> pixel(const std::string& png, double x, double y, int* width = nullptr,
                         int* height = nullptr) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
  std::array<int, 3> rgb{-1, -1, -1};
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
    if (width) *width = cairo_image_surface_get_width(s);
    if (height) *height = cairo_image_surface_get_height(s);
    std::uint32_t px;
    std::memcpy(&px,
                cairo_image_surface_get_data(s) +
                    std::ptrdiff_t(int(y)) * cairo_image_surface_get_stride(s) + 4 * int(x),
                4);
    rgb = {int((px >> 16) & 255), int((px >> 8) & 255), int(px & 255)};
  }
  cairo_surface_destroy(s);
  return rgb;
}

std::array<int, 3> bytes(const std::array<double, 3>& c) {
  return {int(std::lround(255 * c[0])), int(std::lround(255 * c[1])), int(std::lround(255 * c[2]))};
}

TEST(PlotTicks, NiceValuesCoverTheRange) {
  const Ticks t = nice_ticks(0, 1, 5);
  EXPECT_DOUBLE_EQ(t.step, 0.2);
  ASSERT_EQ(t.values.size(), 6u);
  EXPECT_DOUBLE_EQ(t.values[3], 0.6000000000000001);
  const Ticks u = nice_ticks(-37, 112, 6);
  EXPECT_DOUBLE_EQ(u.step, 50);
  EXPECT_EQ(u.values, (std::vector<double>{0, 50, 100}));
  EXPECT_DOUBLE_EQ(nice_step_at_least(0.0031), 0.005);
  EXPECT_DOUBLE_EQ(nice_step_at_least(7), 10);
  EXPECT_EQ(tick_label(0.6000000000000001, 0.2), "0.6");
  EXPECT_EQ(tick_label(-1e-17, 0.05), "0.00");
  EXPECT_EQ(tick_label(150, 50), "150");
  EXPECT_THROW(nice_ticks(1, 1, 5), std::invalid_argument);
}

TEST(LinePlot, EachSeriesColourIsWhereItsPointsLie) {
  LinePlot p;
  p.title = "SAI over sessions";
  p.x_label = "session";
  p.y_label = "SAI";
  p.series.push_back({"forceps",
                      {1, 2, 3, 4, 5},
                      {0.2, 0.35, 0.3, 0.5, 0.55},
                      SeriesStyle::lines_and_markers,
                      std::array<double, 3>{0.0, 0.45, 0.70}});
  p.series.push_back({"hook",
                      {1, 2, 3, 4, 5},
                      {-0.1, 0.0, 0.1, 0.12, 0.3},
                      SeriesStyle::markers,
                      std::array<double, 3>{0.84, 0.37, 0.0}});
  p.reference = ReferenceLine{0.45, "threshold 0.45", {0.3, 0.3, 0.3}};
  const std::string png = kDir + "imasim_line_plot.png";
  const PlotArea a = write_line_plot_png(p, png);
  int w = 0, h = 0;
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t i = 0; i < 5; ++i) {
      const auto [x, y] = a.point_position(p, s, i);
      const std::array<int, 3> got = pixel(png, x, y, &w, &h);
      const std::array<int, 3> want = bytes(*p.series[s].rgb);
      for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(got[k], want[k], 2) << "series " << s << " point " << i;
    }
  EXPECT_EQ(w, p.width);
  EXPECT_EQ(h, p.height);
  // Between the hook's markers (no line) the plot is white; the forceps' line joins its points.
  const auto [hx0, hy0] = a.point_position(p, 1, 0);
  const auto [hx1, hy1] = a.point_position(p, 1, 1);
  const double mx = (hx0 + hx1) / 2, my = (hy0 + hy1) / 2;
  EXPECT_EQ(pixel(png, mx, my), (std::array<int, 3>{255, 255, 255}));
  const auto [fx0, fy0] = a.point_position(p, 0, 2);
  const auto [fx1, fy1] = a.point_position(p, 0, 3);
  const std::array<int, 3> mid = pixel(png, (fx0 + fx1) / 2, (fy0 + fy1) / 2);
  EXPECT_NEAR(mid[2], 178, 40);  // the line's blue, antialiased
  EXPECT_LT(mid[0], 80);
  // The axes hold every point and the reference line.
  EXPECT_LE(a.y0, -0.1);
  EXPECT_GE(a.y1, 0.55);
  EXPECT_LT(a.x0, 1);
  EXPECT_GT(a.x1, 5);
}

TEST(LinePlot, BarsOfTwoGroupsStandSideBySide) {
  LinePlot p;
  p.title = "SAI per trial";
  p.x_label = "trial";
  p.y_label = "SAI";
  p.series.push_back({"dynamic", {1, 2, 3}, {0.583, 0.621, 0.545}, SeriesStyle::bars, {}});
  p.series.push_back({"static", {1, 2, 3}, {0.247, 0.268, 0.221}, SeriesStyle::bars, {}});
  const std::string png = kDir + "imasim_bar_plot.png";
  const PlotArea a = write_line_plot_png(p, png);
  EXPECT_EQ(a.y0, 0);  // bars stand on zero
  EXPECT_NEAR(a.bar_width, 0.4, 1e-12);
  for (std::size_t s = 0; s < 2; ++s) {
    const auto [x, y] = a.point_position(p, s, 1);
    const auto [x0, base] = a.to_picture(2, 0);
    EXPECT_NEAR(x, x0 + (s == 0 ? -0.2 : 0.2) * a.width / (a.x1 - a.x0), 1e-9);
    const std::array<int, 3> got = pixel(png, x, (y + base) / 2);  // halfway up the bar
    const std::array<int, 3> want = bytes(plot_palette_colour(s));
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(got[k], want[k], 1) << "series " << s;
  }
}

TEST(LinePlot, BadSeriesAndPathsAreRefused) {
  LinePlot p;
  EXPECT_THROW(line_plot_area(p), std::invalid_argument);  // nothing to plot
  p.series.push_back({"a", {1, 2}, {1}, SeriesStyle::markers, {}});
  EXPECT_THROW(line_plot_area(p), std::invalid_argument);
  p.series[0].y = {1, NAN};
  EXPECT_THROW(line_plot_area(p), std::invalid_argument);
  p.series[0].y = {1, 1};
  p.width = 50;
  EXPECT_THROW(line_plot_area(p), std::invalid_argument);
  p.width = 600;
  const PlotArea flat = line_plot_area(p);  // a flat series still gets a window
  EXPECT_LT(flat.y0, 1);
  EXPECT_GT(flat.y1, 1);
  const std::string missing = kDir + "no_such_directory/p.png";
  try {
    write_line_plot_png(p, missing);
    FAIL();
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
}

}  // namespace
