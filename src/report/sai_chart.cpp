#include "report/sai_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/text_format.hpp"

namespace imasim::report {

namespace {

constexpr double kWidth = 560, kHeight = 280;
constexpr double kLeft = 64, kRight = 16, kTop = 16, kBottom = 44;

std::string num(double v) {
  char out[32];
  std::snprintf(out, sizeof out, "%.1f", v);
  return out;
}

// A tick step of 1, 2 or 5 times a power of ten giving about five ticks over `span`.
double tick_step(double span) {
  const double raw = span / 5;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10 * power;
}

}  // namespace

std::string mode_colour(const std::string& mode, std::size_t index) {
  if (mode == "dynamic") return "#d9620b";
  if (mode == "static") return "#1f6fb2";
  static const char* const kOthers[] = {"#2e8b57", "#8e44ad", "#7f6000", "#555555"};
  return kOthers[index % 4];
}

std::string sai_chart_svg(const SaiComparison& c) {
  double lo = 0, hi = 0;
  bool any = false;
  for (const SaiGroup& g : c.groups) {
    for (const double v : g.values) {
      lo = any ? std::min(lo, v) : v;
      hi = any ? std::max(hi, v) : v;
      any = true;
    }
    if (!g.values.empty()) {
      lo = std::min(lo, g.summary.mean - g.summary.sd);
      hi = std::max(hi, g.summary.mean + g.summary.sd);
    }
  }
  if (!any) return {};
  lo = std::min(lo, 0.0);  // zero (no asymmetry) is always in view
  hi = std::max(hi, 0.0);
  if (hi - lo < 1e-9) hi = lo + 1;
  const double step = tick_step(hi - lo);
  lo = std::floor(lo / step) * step;
  hi = std::ceil(hi / step) * step;
  const double plot_w = kWidth - kLeft - kRight, plot_h = kHeight - kTop - kBottom;
  auto y_of = [&](double v) { return kTop + (hi - v) / (hi - lo) * plot_h; };

  std::string svg = "<svg class=\"chart\" role=\"img\" viewBox=\"0 0 " + num(kWidth) + " " +
                    num(kHeight) + "\" width=\"" + num(kWidth) + "\" height=\"" + num(kHeight) +
                    "\"><title>SAI of the " + html_escape(c.instrument) + " per trial</title>";
  for (double v = lo; v <= hi + step / 2; v += step) {
    const std::string y = num(y_of(v));
    const bool zero = std::abs(v) < step / 2;
    svg += "<line x1=\"" + num(kLeft) + "\" x2=\"" + num(kWidth - kRight) + "\" y1=\"" + y +
           "\" y2=\"" + y + "\" stroke=\"" + (zero ? "#888" : "#e3e6ea") + "\"/>";
    svg += "<text x=\"" + num(kLeft - 8) + "\" y=\"" + num(y_of(v) + 4) +
           "\" text-anchor=\"end\" font-size=\"12\" fill=\"#444\">" + fixed(v, 2) + "</text>";
  }
  svg += "<text transform=\"translate(16 " + num(kTop + plot_h / 2) +
         ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\" fill=\"#444\">SAI of the " +
         html_escape(c.instrument) + "</text>";
  const double band = plot_w / double(c.groups.size());
  for (std::size_t k = 0; k < c.groups.size(); ++k) {
    const SaiGroup& g = c.groups[k];
    const std::string colour = mode_colour(g.mode, k);
    const double centre = kLeft + band * (double(k) + 0.5);
    svg += "<text x=\"" + num(centre) + "\" y=\"" + num(kHeight - 16) +
           "\" text-anchor=\"middle\" font-size=\"13\" fill=\"#222\">" + html_escape(g.mode) +
           " (n = " + std::to_string(g.values.size()) + ")</text>";
    for (std::size_t i = 0; i < g.values.size(); ++i) {
      // Spread the dots sideways in a fixed pattern so equal values stay visible.
      const double dx = (double(i % 7) - 3) * 7;
      svg += "<circle cx=\"" + num(centre - 30 + dx) + "\" cy=\"" + num(y_of(g.values[i])) +
             "\" r=\"4.5\" fill=\"" + colour + "\" fill-opacity=\"0.75\"/>";
    }
    if (g.values.empty()) continue;
    const double x = centre + 34;
    const double m = g.summary.mean, s = g.summary.sd;
    svg += "<line x1=\"" + num(x) + "\" x2=\"" + num(x) + "\" y1=\"" + num(y_of(m - s)) +
           "\" y2=\"" + num(y_of(m + s)) + "\" stroke=\"" + colour + "\" stroke-width=\"2\"/>";
    for (const double v : {m - s, m + s})
      svg += "<line x1=\"" + num(x - 6) + "\" x2=\"" + num(x + 6) + "\" y1=\"" + num(y_of(v)) +
             "\" y2=\"" + num(y_of(v)) + "\" stroke=\"" + colour + "\" stroke-width=\"2\"/>";
    svg += "<line x1=\"" + num(x - 14) + "\" x2=\"" + num(x + 14) + "\" y1=\"" + num(y_of(m)) +
           "\" y2=\"" + num(y_of(m)) + "\" stroke=\"" + colour + "\" stroke-width=\"3\"/>";
  }
  svg += "</svg>";
  return svg;
}

}  // namespace imasim::report
