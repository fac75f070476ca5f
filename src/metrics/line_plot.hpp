#pragma once
// A small 2-D plot as PNG (cairo): named series of (x, y) points drawn as lines with markers, as
// markers alone or as bars (bars of several series side by side at each x), axes with nice ticks
// and labels, a legend, a title and an optional horizontal reference line (a threshold). For the
// trainee's history (a metric over session number) and the study report (SAI per trial per group).
#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace imasim::metrics {

enum class SeriesStyle { lines_and_markers, markers, bars };

struct PlotSeries {
  std::string name;  // in the legend
  std::vector<double> x, y;
  SeriesStyle style = SeriesStyle::lines_and_markers;
  std::optional<std::array<double, 3>> rgb;  // default: plot_palette_colour(its index)
};

struct ReferenceLine {
  double y = 0;
  std::string label;  // drawn above the line's right end ("threshold 0.5")
  std::array<double, 3> rgb{0.35, 0.35, 0.35};
};

struct LinePlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  std::optional<ReferenceLine> reference;
  int width = 900, height = 560;  // (unit: px), at least 400 x 300
  bool y_from_zero = false;       // the y axis includes 0 (always so with bars)
};

// The plot area in the picture and the data window it shows.
struct PlotArea {
  int left = 0, top = 0, width = 0, height = 0;  // (unit: px)
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;         // data at the left, right, bottom and top edges
  double bar_width = 0;                          // in x units, of one bar (0 without bars)

  std::array<double, 2> to_picture(double x, double y) const;
  // Where series `series` draws the bar or marker of its point `index` (bars are offset beside
  // each other).
  std::array<double, 2> point_position(const LinePlot& plot, std::size_t series,
                                       std::size_t index) const;
};

// The palette (Okabe and Ito's, told apart with colour-blindness), repeating after eight.
std::array<double, 3> plot_palette_colour(std::size_t index);

// Each throws std::invalid_argument for a series whose x and y differ in length, a value that is
// not finite, no point at all, or a size out of range.
PlotArea line_plot_area(const LinePlot& plot);

// Draws and writes the PNG; throws OutputError naming the path when cairo fails or the file cannot
// be written (never over one of `inputs`).
PlotArea write_line_plot_png(const LinePlot& plot, const std::string& png_path,
                             std::span<const std::string> inputs = {});

}  // namespace imasim::metrics
