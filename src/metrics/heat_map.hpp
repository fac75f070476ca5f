#pragma once
// Heat maps of tool positions as in Fig. 13 of the paper: the tips projected orthogonally onto a
// HeatMapFrame's plane, a Gaussian kernel density of them on the picture's pixels, coloured from
// transparent (no samples: the neutral background shows) to the hot end of metrics/colour_map.hpp,
// with a colour bar, the IMA's centerline in red, the frame's outlines with a legend, millimetre
// axes, a scale bar and a title. PNG through cairo.
//
// Density: the share of samples per mm^2, f(x) = (1/n) sum_i K(x - x_i) with K the 2-D Gaussian of
// standard deviation `bandwidth` (1/(2 pi h^2) exp(-|d|^2 / 2 h^2)), at each pixel's centre; it
// integrates to 1 over the plane. Terms beyond 5 h (below 4e-6 of the peak) are left out.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "metrics/heat_map_frame.hpp"

namespace imasim::metrics {

struct HeatMapStyle {
  std::string title = "Tool-tip density";
  std::string subtitle;            // e.g. "SAI = 0.583"; none when empty
  int width = 1100, height = 700;  // the picture (unit: px), at least 480 x 360
  double bandwidth = 0.001;        // the kernel's standard deviation (unit: m)
  // Top of the colour scale (unit: share of samples per mm^2); 0: the map's own maximum. Give the
  // same value to maps that are to be compared.
  double density_max = 0;
  double view_margin = 0.06;  // added on each side, as a share of the drawn extent
};

// Where the plane is drawn: the plot area in the picture and the plane window it shows, with
// equal scale on both axes (u to the right, v up).
struct HeatMapView {
  int left = 0, top = 0, width = 0, height = 0;  // the plot area (unit: px)
  double u_min = 0, v_max = 0;                   // plane coordinates of its top-left corner (m)
  double metres_per_pixel = 0;

  // Plane coordinates of the centre of plot pixel (col, row), row 0 at the top.
  PlanePoint pixel_centre(int col, int row) const;
  // Picture coordinates (x right, y down; unit: px) of a plane point.
  std::array<double, 2> to_picture(const PlanePoint& p) const;
};

struct DensityGrid {
  HeatMapView view;
  // Per plot pixel, row-major from the top row (unit: share of samples per mm^2).
  std::vector<double> density;
  double max = 0;
  std::size_t samples = 0;

  double at(int col, int row) const {
    return density[std::size_t(row) * std::size_t(view.width) + std::size_t(col)];
  }
};

// Each throws std::invalid_argument for a style out of range or a point that is not finite.
HeatMapView heat_map_view(const HeatMapFrame& frame, std::span<const Vec3> points,
                          const HeatMapStyle& style);
DensityGrid heat_map_density(const HeatMapFrame& frame, std::span<const Vec3> points,
                             const HeatMapStyle& style);

// Draws and writes the PNG; returns the density drawn. Throws OutputError naming the path when
// cairo fails or the file cannot be written (never over one of `inputs`).
DensityGrid write_heat_map_png(const HeatMapFrame& frame, std::span<const Vec3> points,
                               const HeatMapStyle& style, const std::string& png_path,
                               std::span<const std::string> inputs = {});

// The centerline's colour (red) and the plot area's background (neutral grey).
inline constexpr std::array<double, 3> kCenterlineRgb{0.85, 0.0, 0.0};
inline constexpr std::array<double, 3> kHeatMapBackgroundRgb{0.93, 0.93, 0.93};

}  // namespace imasim::metrics
