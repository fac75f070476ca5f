#include "metrics/heat_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

#include "metrics/colour_map.hpp"
#include "metrics/plot_canvas.hpp"
#include "metrics/plot_ticks.hpp"

namespace imasim::metrics {

namespace {

// Layout (unit: px).
constexpr int kMargin = 24, kLeftBand = 66, kBottomBand = 54, kRightPanel = 236;
constexpr int kTitleBand = 38, kSubtitleBand = 28;
constexpr int kMinWidth = 480, kMinHeight = 360, kMaxSide = 8000;
constexpr double kCutoff = 5;   // kernel terms beyond this many bandwidths are left out
constexpr double kFade = 0.04;  // densities below this share of the top fade in from transparent
constexpr double kMm2PerM2 = 1e6;

const TextStyle kTitle{22, true};
const TextStyle kSubtitle{16, false, {0.25, 0.25, 0.25}};
const TextStyle kLabel{14};
const TextStyle kTick{12.5, false, {0.2, 0.2, 0.2}};

void check_style(const HeatMapStyle& s) {
  if (s.width < kMinWidth || s.width > kMaxSide || s.height < kMinHeight || s.height > kMaxSide)
    throw std::invalid_argument("heat map size " + std::to_string(s.width) + " x " +
                                std::to_string(s.height) + " px is outside " +
                                std::to_string(kMinWidth) + " x " + std::to_string(kMinHeight) +
                                " to " + std::to_string(kMaxSide) + " px");
  if (!std::isfinite(s.bandwidth) || !(s.bandwidth > 0) || s.bandwidth > 1)
    throw std::invalid_argument("heat map bandwidth must be in (0, 1] m");
  if (!std::isfinite(s.density_max) || s.density_max < 0)
    throw std::invalid_argument("heat map density_max must be finite and >= 0");
  if (!std::isfinite(s.view_margin) || s.view_margin < 0 || s.view_margin > 1)
    throw std::invalid_argument("heat map view_margin must be in [0, 1]");
}

int title_height(const HeatMapStyle& s) {
  return (s.title.empty() ? 0 : kTitleBand) + (s.subtitle.empty() ? 0 : kSubtitleBand);
}

struct Bounds {
  double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
  void add(const PlanePoint& p) {
    u0 = std::min(u0, p.x());
    u1 = std::max(u1, p.x());
    v0 = std::min(v0, p.y());
    v1 = std::max(v1, p.y());
  }
  bool empty() const { return !(u0 <= u1); }
};

std::vector<PlanePoint> projected_samples(const HeatMapFrame& f, std::span<const Vec3> points) {
  std::vector<PlanePoint> out = project(f, points);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!std::isfinite(out[i].x()) || !std::isfinite(out[i].y()))
      throw std::invalid_argument("heat map sample " + std::to_string(i) + " is not finite");
  return out;
}

HeatMapView view_of(const HeatMapFrame& f, std::span<const PlanePoint> samples,
                    const HeatMapStyle& s) {
  check_style(s);
  check_heat_map_frame(f, "the heat map frame");
  Bounds b;
  for (const Vec3& p : f.centerline)
    b.add(project(f, p));
  for (const HeatMapOutline& o : f.outlines)
    for (const Vec3& p : o.points)
      b.add(project(f, p));
  for (const PlanePoint& p : samples)
    b.add(p);
  if (b.empty()) b = {-0.01, 0.01, -0.01, 0.01};
  const double pad = std::max(s.view_margin * std::max(b.u1 - b.u0, b.v1 - b.v0), 3 * s.bandwidth);
  HeatMapView v;
  v.left = kMargin + kLeftBand;
  v.top = kMargin + title_height(s);
  v.width = s.width - v.left - kRightPanel - kMargin;
  v.height = s.height - v.top - kBottomBand - kMargin;
  v.metres_per_pixel = std::max((b.u1 - b.u0 + 2 * pad) / double(v.width),
                                (b.v1 - b.v0 + 2 * pad) / double(v.height));
  v.u_min = (b.u0 + b.u1) / 2 - v.metres_per_pixel * double(v.width) / 2;
  v.v_max = (b.v0 + b.v1) / 2 + v.metres_per_pixel * double(v.height) / 2;
  return v;
}

DensityGrid density_of(const HeatMapView& view, std::span<const PlanePoint> samples, double h) {
  DensityGrid g;
  g.view = view;
  g.samples = samples.size();
  g.density.assign(std::size_t(view.width) * std::size_t(view.height), 0.0);
  const double mpp = view.metres_per_pixel, reach = kCutoff * h;
  std::vector<double> wu, wv;
  for (const PlanePoint& p : samples) {
    // Columns and rows whose centres lie within the cutoff.
    const int c0 = std::max(0, int(std::ceil((p.x() - reach - view.u_min) / mpp - 0.5)));
    const int c1 =
        std::min(view.width - 1, int(std::floor((p.x() + reach - view.u_min) / mpp - 0.5)));
    const int r0 = std::max(0, int(std::ceil((view.v_max - (p.y() + reach)) / mpp - 0.5)));
    const int r1 =
        std::min(view.height - 1, int(std::floor((view.v_max - (p.y() - reach)) / mpp - 0.5)));
    if (c0 > c1 || r0 > r1) continue;
    wu.resize(std::size_t(c1 - c0 + 1));
    wv.resize(std::size_t(r1 - r0 + 1));
    for (int c = c0; c <= c1; ++c) {
      const double d = view.u_min + (c + 0.5) * mpp - p.x();
      wu[std::size_t(c - c0)] = std::exp(-d * d / (2 * h * h));
    }
    for (int r = r0; r <= r1; ++r) {
      const double d = view.v_max - (r + 0.5) * mpp - p.y();
      wv[std::size_t(r - r0)] = std::exp(-d * d / (2 * h * h));
    }
    for (int r = r0; r <= r1; ++r) {
      double* row = g.density.data() + std::size_t(r) * std::size_t(view.width);
      const double w = wv[std::size_t(r - r0)];
      for (int c = c0; c <= c1; ++c)
        row[c] += w * wu[std::size_t(c - c0)];
    }
  }
  const double scale =
      samples.empty() ? 0.0
                      : 1.0 / (double(samples.size()) * 2 * std::numbers::pi * h * h * kMm2PerM2);
  for (double& d : g.density) {
    d *= scale;
    g.max = std::max(g.max, d);
  }
  return g;
}

std::uint8_t byte_of(double x) {
  return std::uint8_t(std::lround(std::clamp(x, 0.0, 1.0) * 255));
}

// The density as an image of the plot area: premultiplied ARGB, transparent where zero.
void paint_density(PlotCanvas& canvas, const DensityGrid& g, double top) {
  const HeatMapView& v = g.view;
  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, v.width, v.height);
  const cairo_status_t status = cairo_surface_status(image);
  if (status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(image);
    canvas.require(status, "making the density image");
  }
  cairo_surface_flush(image);
  unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  for (int r = 0; r < v.height; ++r) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + std::ptrdiff_t(r) * stride);
    for (int c = 0; c < v.width; ++c) {
      const double t = g.at(c, r) / top;
      if (!(t > 0)) {
        row[c] = 0;
        continue;
      }
      const double alpha = std::min(1.0, t / kFade);
      const Rgb rgb = heat_colour(t);
      row[c] = (std::uint32_t(byte_of(alpha)) << 24) |
               (std::uint32_t(byte_of(rgb[0] * alpha)) << 16) |
               (std::uint32_t(byte_of(rgb[1] * alpha)) << 8) | byte_of(rgb[2] * alpha);
    }
  }
  cairo_surface_mark_dirty(image);
  cairo_set_source_surface(canvas.cr(), image, v.left, v.top);
  cairo_paint(canvas.cr());
  cairo_surface_destroy(image);
}

void trace(PlotCanvas& canvas, const HeatMapView& v, const HeatMapFrame& f,
           std::span<const Vec3> points, bool closed) {
  cairo_t* cr = canvas.cr();
  cairo_new_path(cr);
  for (const Vec3& p : points) {
    const auto [x, y] = v.to_picture(project(f, p));
    cairo_line_to(cr, x, y);
  }
  if (closed) cairo_close_path(cr);
}

void draw_anatomy(PlotCanvas& canvas, const HeatMapView& v, const HeatMapFrame& f) {
  cairo_t* cr = canvas.cr();
  cairo_save(cr);
  cairo_rectangle(cr, v.left, v.top, v.width, v.height);
  cairo_clip(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const HeatMapOutline& o : f.outlines) {
    trace(canvas, v, f, o.points, o.closed);
    canvas.set_colour(o.rgb);
    cairo_set_line_width(cr, 2);
    cairo_stroke(cr);
  }
  if (f.centerline.size() >= 2) {
    // A white casing keeps the red line visible over any density.
    trace(canvas, v, f, f.centerline, false);
    canvas.set_colour({1, 1, 1}, 0.9);
    cairo_set_line_width(cr, 6);
    cairo_stroke_preserve(cr);
    canvas.set_colour(kCenterlineRgb);
    cairo_set_line_width(cr, 3);
    cairo_stroke(cr);
  }
  cairo_restore(cr);
}

void draw_axes(PlotCanvas& canvas, const HeatMapView& v) {
  cairo_t* cr = canvas.cr();
  canvas.set_colour({0.3, 0.3, 0.3});
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, v.left + 0.5, v.top + 0.5, v.width - 1, v.height - 1);
  cairo_stroke(cr);
  const double mm = 1000 * v.metres_per_pixel;  // mm per pixel
  const double u0 = 1000 * v.u_min, u1 = u0 + mm * v.width;
  const double v1 = 1000 * v.v_max, v0 = v1 - mm * v.height;
  const double bottom = v.top + v.height;
  const Ticks tu = nice_ticks(u0, u1, std::max(3, v.width / 90));
  for (double t : tu.values) {
    const double x = v.left + (t - u0) / mm;
    cairo_move_to(cr, x, bottom);
    cairo_line_to(cr, x, bottom + 5);
    canvas.text(tick_label(t, tu.step), x, bottom + 8, HAlign::centre, VAlign::top, kTick);
  }
  const Ticks tv = nice_ticks(v0, v1, std::max(3, v.height / 80));
  for (double t : tv.values) {
    const double y = v.top + (v1 - t) / mm;
    cairo_move_to(cr, v.left, y);
    cairo_line_to(cr, v.left - 5, y);
    canvas.text(tick_label(t, tv.step), v.left - 8, y, HAlign::right, VAlign::middle, kTick);
  }
  canvas.set_colour({0.3, 0.3, 0.3});
  cairo_stroke(cr);
  canvas.text("along the IMA (mm)", v.left + v.width / 2.0, bottom + 30, HAlign::centre,
              VAlign::top, kLabel);
  TextStyle turned = kLabel;
  turned.angle = std::numbers::pi / 2;
  canvas.text("across the IMA (mm)", v.left - 50, v.top + v.height / 2.0, HAlign::centre,
              VAlign::top, turned);
}

void draw_scale_bar(PlotCanvas& canvas, const HeatMapView& v) {
  cairo_t* cr = canvas.cr();
  const double mm = 1000 * v.metres_per_pixel;
  const double length_mm = nice_step_at_least(mm * v.width / 7);
  const double length = length_mm / mm;
  const double x = v.left + 18, y = v.top + v.height - 18;
  canvas.set_colour({1, 1, 1}, 0.85);
  cairo_rectangle(cr, x - 8, y - 30, length + 16, 40);
  cairo_fill(cr);
  canvas.set_colour({0.05, 0.05, 0.05});
  cairo_rectangle(cr, x, y - 3, length, 6);
  cairo_fill(cr);
  canvas.text(tick_label(length_mm, length_mm) + " mm", x + length / 2, y - 8, HAlign::centre,
              VAlign::baseline, kLabel);
}

// The colour bar with its ticks, then the legend below it; returns nothing, draws in the right
// panel.
void draw_colour_bar(PlotCanvas& canvas, const HeatMapView& v, double top_density) {
  cairo_t* cr = canvas.cr();
  const double x = v.left + v.width + 34, bar_w = 22;
  const double y0 = v.top + 46, bar_h = std::max(120.0, 0.48 * v.height);
  canvas.text("Tip density", x, v.top + 2, HAlign::left, VAlign::top, {14, true});
  canvas.text("share of samples per mm²", x, v.top + 22, HAlign::left, VAlign::top, kTick);
  cairo_pattern_t* ramp = cairo_pattern_create_linear(0, y0 + bar_h, 0, y0);
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    const Rgb c = heat_colour(t);
    cairo_pattern_add_color_stop_rgba(ramp, t, c[0], c[1], c[2], std::min(1.0, t / kFade));
  }
  canvas.set_colour(kHeatMapBackgroundRgb);
  cairo_rectangle(cr, x, y0, bar_w, bar_h);
  cairo_fill_preserve(cr);
  cairo_set_source(cr, ramp);
  cairo_fill(cr);
  cairo_pattern_destroy(ramp);
  canvas.set_colour({0.3, 0.3, 0.3});
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, x + 0.5, y0 + 0.5, bar_w - 1, bar_h - 1);
  cairo_stroke(cr);
  const Ticks ticks = nice_ticks(0, top_density, 5);
  for (double t : ticks.values) {
    const double y = y0 + bar_h * (1 - t / top_density);
    cairo_move_to(cr, x + bar_w, y);
    cairo_line_to(cr, x + bar_w + 5, y);
    canvas.text(tick_label(t, ticks.step), x + bar_w + 8, y, HAlign::left, VAlign::middle, kTick);
  }
  canvas.set_colour({0.3, 0.3, 0.3});
  cairo_stroke(cr);
}

void legend_entry(PlotCanvas& canvas, double x, double y, const Rgb& rgb, bool cased,
                  const std::string& name) {
  cairo_t* cr = canvas.cr();
  if (cased) {
    canvas.set_colour({1, 1, 1});
    cairo_set_line_width(cr, 6);
    cairo_move_to(cr, x, y);
    cairo_line_to(cr, x + 30, y);
    cairo_stroke(cr);
  }
  canvas.set_colour(rgb);
  cairo_set_line_width(cr, cased ? 3 : 2);
  cairo_move_to(cr, x, y);
  cairo_line_to(cr, x + 30, y);
  cairo_stroke(cr);
  canvas.text(name, x + 40, y, HAlign::left, VAlign::middle, kLabel);
}

void draw_legend(PlotCanvas& canvas, const HeatMapView& v, const HeatMapFrame& f,
                 std::size_t samples) {
  const double x = v.left + v.width + 34;
  double y = v.top + 46 + std::max(120.0, 0.48 * v.height) + 40;
  canvas.text("Anatomy", x, y, HAlign::left, VAlign::top, {14, true});
  y += 34;
  if (!f.centerline.empty()) {
    legend_entry(canvas, x, y, kCenterlineRgb, true, "IMA centerline");
    y += 24;
  }
  for (const HeatMapOutline& o : f.outlines) {
    legend_entry(canvas, x, y, o.rgb, false, o.name);
    y += 24;
  }
  canvas.text("n = " + std::to_string(samples) + " samples", x, y + 6, HAlign::left, VAlign::top,
              kTick);
}

}  // namespace

PlanePoint HeatMapView::pixel_centre(int col, int row) const {
  return {u_min + (col + 0.5) * metres_per_pixel, v_max - (row + 0.5) * metres_per_pixel};
}

std::array<double, 2> HeatMapView::to_picture(const PlanePoint& p) const {
  return {left + (p.x() - u_min) / metres_per_pixel, top + (v_max - p.y()) / metres_per_pixel};
}

HeatMapView heat_map_view(const HeatMapFrame& f, std::span<const Vec3> points,
                          const HeatMapStyle& s) {
  return view_of(f, projected_samples(f, points), s);
}

DensityGrid heat_map_density(const HeatMapFrame& f, std::span<const Vec3> points,
                             const HeatMapStyle& s) {
  const std::vector<PlanePoint> samples = projected_samples(f, points);
  return density_of(view_of(f, samples, s), samples, s.bandwidth);
}

DensityGrid write_heat_map_png(const HeatMapFrame& f, std::span<const Vec3> points,
                               const HeatMapStyle& s, const std::string& png_path,
                               std::span<const std::string> inputs) {
  DensityGrid g = heat_map_density(f, points, s);
  const HeatMapView& v = g.view;
  // With no samples the scale is nominal: nothing is coloured.
  const double top = s.density_max > 0 ? s.density_max : g.max > 0 ? g.max : 1.0;
  PlotCanvas canvas(s.width, s.height, png_path);
  if (!s.title.empty()) canvas.text(s.title, kMargin, kMargin, HAlign::left, VAlign::top, kTitle);
  if (!s.subtitle.empty())
    canvas.text(s.subtitle, kMargin, kMargin + (s.title.empty() ? 0 : kTitleBand), HAlign::left,
                VAlign::top, kSubtitle);
  canvas.set_colour(kHeatMapBackgroundRgb);
  cairo_rectangle(canvas.cr(), v.left, v.top, v.width, v.height);
  cairo_fill(canvas.cr());
  paint_density(canvas, g, top);
  draw_anatomy(canvas, v, f);
  draw_scale_bar(canvas, v);
  draw_axes(canvas, v);
  draw_colour_bar(canvas, v, top);
  draw_legend(canvas, v, f, g.samples);
  canvas.save(inputs);
  return g;
}

}  // namespace imasim::metrics
