#include "metrics/line_plot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "metrics/plot_canvas.hpp"
#include "metrics/plot_ticks.hpp"

namespace imasim::metrics {

namespace {

// Layout (unit: px).
constexpr int kPlotMargin = 24, kPlotTitleBand = 40, kPlotLegendBand = 30, kPlotLeftBand = 74,
              kPlotBottomBand = 56;
constexpr int kPlotRightPad = 20, kPlotMinWidth = 400, kPlotMinHeight = 300, kPlotMaxSide = 8000;
constexpr double kMarkerRadius = 4.5;
constexpr double kBarSlot = 0.8;  // share of the x spacing the bars at one x fill

const TextStyle kPlotTitle{20, true};
const TextStyle kPlotLabel{14};
const TextStyle kPlotTick{12.5, false, {0.2, 0.2, 0.2}};

constexpr std::array<std::array<double, 3>, 8> kPalette{{{0.000, 0.447, 0.698},
                                                         {0.835, 0.369, 0.000},
                                                         {0.000, 0.620, 0.451},
                                                         {0.800, 0.475, 0.655},
                                                         {0.337, 0.706, 0.914},
                                                         {0.902, 0.624, 0.000},
                                                         {0.941, 0.894, 0.259},
                                                         {0.0, 0.0, 0.0}}};

Rgb colour_of(const LinePlot& p, std::size_t s) {
  return p.series[s].rgb ? *p.series[s].rgb : plot_palette_colour(s);
}

std::size_t bar_series_count(const LinePlot& p) {
  return std::size_t(std::count_if(p.series.begin(), p.series.end(), [](const PlotSeries& s) {
    return s.style == SeriesStyle::bars;
  }));
}

// The bar's place among the bar series (0 for the first bar series).
std::size_t bar_rank(const LinePlot& p, std::size_t series) {
  std::size_t rank = 0;
  for (std::size_t s = 0; s < series; ++s)
    rank += p.series[s].style == SeriesStyle::bars ? 1 : 0;
  return rank;
}

void check_plot(const LinePlot& p) {
  if (p.width < kPlotMinWidth || p.width > kPlotMaxSide || p.height < kPlotMinHeight ||
      p.height > kPlotMaxSide)
    throw std::invalid_argument(
        "plot size " + std::to_string(p.width) + " x " + std::to_string(p.height) +
        " px is outside " + std::to_string(kPlotMinWidth) + " x " + std::to_string(kPlotMinHeight) +
        " to " + std::to_string(kPlotMaxSide) + " px");
  std::size_t points = 0;
  for (const PlotSeries& s : p.series) {
    if (s.x.size() != s.y.size())
      throw std::invalid_argument("plot series '" + s.name + "' has " + std::to_string(s.x.size()) +
                                  " x values and " + std::to_string(s.y.size()) + " y values");
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]))
        throw std::invalid_argument("plot series '" + s.name + "': point " + std::to_string(i) +
                                    " is not finite");
    points += s.x.size();
  }
  if (points == 0) throw std::invalid_argument("a plot needs at least one point");
  if (p.reference && !std::isfinite(p.reference->y))
    throw std::invalid_argument("the plot's reference line is not finite");
}

bool all_integers(const LinePlot& p) {
  for (const PlotSeries& s : p.series)
    for (double x : s.x)
      if (x != std::round(x)) return false;
  return true;
}

Ticks x_ticks(const LinePlot& p, const PlotArea& a) {
  Ticks t = nice_ticks(a.x0, a.x1, std::max(3, a.width / 100));
  if (t.step < 1 && all_integers(p)) {  // session or trial numbers: whole numbers only
    t = {{}, 1};
    for (double x = std::ceil(a.x0); x <= a.x1; ++x)
      t.values.push_back(x);
  }
  return t;
}

void draw_series(PlotCanvas& canvas, const LinePlot& p, const PlotArea& a) {
  cairo_t* cr = canvas.cr();
  cairo_save(cr);
  cairo_rectangle(cr, a.left, a.top, a.width, a.height);
  cairo_clip(cr);
  for (std::size_t s = 0; s < p.series.size(); ++s) {
    const PlotSeries& series = p.series[s];
    const Rgb rgb = colour_of(p, s);
    if (series.style == SeriesStyle::bars) {
      const double w = a.bar_width * a.width / (a.x1 - a.x0);
      const double base = a.to_picture(0, std::clamp(0.0, a.y0, a.y1))[1];
      for (std::size_t i = 0; i < series.x.size(); ++i) {
        const auto [x, y] = a.point_position(p, s, i);
        cairo_rectangle(cr, x - w / 2, std::min(y, base), w, std::abs(base - y));
      }
      canvas.set_colour(rgb);
      cairo_fill(cr);
      continue;
    }
    if (series.style == SeriesStyle::lines_and_markers && series.x.size() >= 2) {
      cairo_new_path(cr);
      for (std::size_t i = 0; i < series.x.size(); ++i) {
        const auto [x, y] = a.point_position(p, s, i);
        cairo_line_to(cr, x, y);
      }
      canvas.set_colour(rgb);
      cairo_set_line_width(cr, 2.2);
      cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
      cairo_stroke(cr);
    }
    for (std::size_t i = 0; i < series.x.size(); ++i) {
      const auto [x, y] = a.point_position(p, s, i);
      cairo_new_sub_path(cr);
      cairo_arc(cr, x, y, kMarkerRadius, 0, 2 * std::numbers::pi);
      canvas.set_colour(rgb);
      cairo_fill_preserve(cr);
      canvas.set_colour({1, 1, 1});
      cairo_set_line_width(cr, 1.2);
      cairo_stroke(cr);
    }
  }
  cairo_restore(cr);
}

void draw_reference(PlotCanvas& canvas, const LinePlot& p, const PlotArea& a) {
  if (!p.reference) return;
  cairo_t* cr = canvas.cr();
  const double y = a.to_picture(0, p.reference->y)[1];
  const double dash[] = {7, 5};
  cairo_save(cr);
  cairo_set_dash(cr, dash, 2, 0);
  canvas.set_colour(p.reference->rgb);
  cairo_set_line_width(cr, 1.6);
  cairo_move_to(cr, a.left, y);
  cairo_line_to(cr, a.left + a.width, y);
  cairo_stroke(cr);
  cairo_restore(cr);
  TextStyle style = kPlotTick;
  style.rgb = p.reference->rgb;
  canvas.text(p.reference->label, a.left + a.width - 6, y - 4, HAlign::right, VAlign::baseline,
              style);
}

void draw_axes(PlotCanvas& canvas, const LinePlot& p, const PlotArea& a) {
  cairo_t* cr = canvas.cr();
  const double bottom = a.top + a.height;
  const Ticks ty = nice_ticks(a.y0, a.y1, std::max(3, a.height / 70));
  for (double t : ty.values) {  // light grid lines first
    const double y = a.to_picture(0, t)[1];
    canvas.set_colour({0.88, 0.88, 0.88});
    cairo_set_line_width(cr, 1);
    cairo_move_to(cr, a.left, std::round(y) + 0.5);
    cairo_line_to(cr, a.left + a.width, std::round(y) + 0.5);
    cairo_stroke(cr);
    canvas.text(tick_label(t, ty.step), a.left - 8, y, HAlign::right, VAlign::middle, kPlotTick);
  }
  const Ticks tx = x_ticks(p, a);
  canvas.set_colour({0.3, 0.3, 0.3});
  for (double t : tx.values) {
    const double x = a.to_picture(t, 0)[0];
    cairo_move_to(cr, x, bottom);
    cairo_line_to(cr, x, bottom + 5);
    canvas.text(tick_label(t, tx.step), x, bottom + 8, HAlign::centre, VAlign::top, kPlotTick);
  }
  canvas.set_colour({0.3, 0.3, 0.3});
  cairo_set_line_width(cr, 1);
  cairo_stroke(cr);
  cairo_rectangle(cr, a.left + 0.5, a.top + 0.5, a.width - 1, a.height - 1);
  cairo_stroke(cr);
  canvas.text(p.x_label, a.left + a.width / 2.0, bottom + 30, HAlign::centre, VAlign::top,
              kPlotLabel);
  TextStyle turned = kPlotLabel;
  turned.angle = std::numbers::pi / 2;
  canvas.text(p.y_label, a.left - 60, a.top + a.height / 2.0, HAlign::centre, VAlign::top, turned);
}

void draw_legend(PlotCanvas& canvas, const LinePlot& p, const PlotArea& a) {
  cairo_t* cr = canvas.cr();
  double x = a.left;
  const double y = a.top - kPlotLegendBand / 2.0 - 2;
  for (std::size_t s = 0; s < p.series.size(); ++s) {
    canvas.set_colour(colour_of(p, s));
    if (p.series[s].style == SeriesStyle::bars) {
      cairo_rectangle(cr, x + 6, y - 7, 16, 14);
      cairo_fill(cr);
    } else {
      if (p.series[s].style == SeriesStyle::lines_and_markers) {
        cairo_set_line_width(cr, 2.2);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + 28, y);
        cairo_stroke(cr);
      }
      cairo_arc(cr, x + 14, y, kMarkerRadius, 0, 2 * std::numbers::pi);
      cairo_fill(cr);
    }
    canvas.text(p.series[s].name, x + 36, y, HAlign::left, VAlign::middle, kPlotLabel);
    x += 36 + canvas.text_width(p.series[s].name, kPlotLabel) + 26;
  }
}

}  // namespace

std::array<double, 3> plot_palette_colour(std::size_t index) {
  return kPalette[index % kPalette.size()];
}

std::array<double, 2> PlotArea::to_picture(double x, double y) const {
  return {left + (x - x0) / (x1 - x0) * width, top + (y1 - y) / (y1 - y0) * height};
}

std::array<double, 2> PlotArea::point_position(const LinePlot& p, std::size_t s,
                                               std::size_t i) const {
  const PlotSeries& series = p.series[s];
  double x = series.x[i];
  if (series.style == SeriesStyle::bars) {
    const double bars = double(bar_series_count(p));
    x += (double(bar_rank(p, s)) - (bars - 1) / 2) * bar_width;
  }
  return to_picture(x, series.y[i]);
}

PlotArea line_plot_area(const LinePlot& p) {
  check_plot(p);
  PlotArea a;
  a.left = kPlotMargin + kPlotLeftBand;
  a.top = kPlotMargin + (p.title.empty() ? 0 : kPlotTitleBand) + kPlotLegendBand;
  a.width = p.width - a.left - kPlotMargin - kPlotRightPad;
  a.height = p.height - a.top - kPlotBottomBand - kPlotMargin;
  std::vector<double> xs;
  double y0 = INFINITY, y1 = -INFINITY;
  for (const PlotSeries& s : p.series) {
    xs.insert(xs.end(), s.x.begin(), s.x.end());
    for (double y : s.y) {
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
  }
  if (p.reference) {
    y0 = std::min(y0, p.reference->y);
    y1 = std::max(y1, p.reference->y);
  }
  const std::size_t bars = bar_series_count(p);
  if (p.y_from_zero || bars > 0) {
    y0 = std::min(y0, 0.0);
    y1 = std::max(y1, 0.0);
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  double spacing = 1;  // between neighbouring x values (x units)
  for (std::size_t i = 1; i < xs.size(); ++i)
    spacing = i == 1 ? xs[i] - xs[i - 1] : std::min(spacing, xs[i] - xs[i - 1]);
  const double x_pad =
      xs.size() > 1 ? std::max(0.04 * (xs.back() - xs.front()), 0.6 * spacing) : 1.0;
  a.x0 = xs.front() - x_pad;
  a.x1 = xs.back() + x_pad;
  a.bar_width = bars > 0 ? kBarSlot * spacing / double(bars) : 0;
  // y: padded, then out to the ticks around it; a flat series gets a unit-wide window.
  if (y1 - y0 < 1e-12 * std::max(1.0, std::abs(y1))) {
    y0 -= 0.5 * std::max(1.0, std::abs(y0));
    y1 += 0.5 * std::max(1.0, std::abs(y1));
  }
  const double pad = 0.06 * (y1 - y0);
  const double lo = y0 == 0 ? 0 : y0 - pad, hi = y1 == 0 ? 0 : y1 + pad;  // bars start at 0
  const Ticks t = nice_ticks(lo, hi, std::max(3, a.height / 70));
  a.y0 = std::floor(lo / t.step + 1e-9) * t.step;
  a.y1 = std::ceil(hi / t.step - 1e-9) * t.step;
  return a;
}

PlotArea write_line_plot_png(const LinePlot& p, const std::string& png_path,
                             std::span<const std::string> inputs) {
  const PlotArea a = line_plot_area(p);
  PlotCanvas canvas(p.width, p.height, png_path);
  if (!p.title.empty())
    canvas.text(p.title, kPlotMargin, kPlotMargin, HAlign::left, VAlign::top, kPlotTitle);
  draw_axes(canvas, p, a);
  draw_reference(canvas, p, a);
  draw_series(canvas, p, a);
  draw_legend(canvas, p, a);
  canvas.save(inputs);
  return a;
}

}  // namespace imasim::metrics
