#pragma once
// A white picture drawn with cairo and saved as PNG, shared by the heat maps and the line plots:
// text in DejaVu Sans (cairo's toy text API; fonts-dejavu-core, scripts/install-deps.sh) placed
// by an anchor, and the PNG written through metrics::OutputFile (checked writes, never over an
// input). Internal to metrics: the public headers do not expose cairo.
#include <cairo.h>

#include <array>
#include <span>
#include <string>

namespace imasim::metrics {

using Rgb = std::array<double, 3>;

// Where a text's anchor point is: its left, centre or right; its top, middle or baseline.
enum class HAlign { left, centre, right };
enum class VAlign { top, middle, baseline };

struct TextStyle {
  double size = 14;  // (unit: px)
  bool bold = false;
  Rgb rgb{0.1, 0.1, 0.1};
  double angle = 0;  // turned counter-clockwise about the anchor (unit: rad)
};

class PlotCanvas {
 public:
  // Throws OutputError naming `png_path` when cairo cannot make the picture.
  PlotCanvas(int width, int height, std::string png_path);
  ~PlotCanvas();
  PlotCanvas(const PlotCanvas&) = delete;
  PlotCanvas& operator=(const PlotCanvas&) = delete;

  cairo_t* cr() const { return cr_; }
  int width() const { return width_; }
  int height() const { return height_; }

  void set_colour(const Rgb& rgb, double alpha = 1);
  void text(const std::string& utf8, double x, double y, HAlign h, VAlign v,
            const TextStyle& style = {});
  double text_width(const std::string& utf8, const TextStyle& style);

  // Throws OutputError naming the path when `status` is a failure (of a helper surface).
  void require(cairo_status_t status, const char* doing) const;

  // Encodes the PNG and writes it to the path; throws OutputError naming the path.
  void save(std::span<const std::string> inputs = {});

 private:
  void check(const char* doing) const { require(status(), doing); }
  cairo_status_t status() const;

  int width_ = 0, height_ = 0;
  std::string path_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

}  // namespace imasim::metrics
