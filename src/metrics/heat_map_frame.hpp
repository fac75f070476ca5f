#pragma once
// The plane a heat map projects onto (Fig. 13 of the paper): the chest wall's plane, as an origin
// and two orthonormal in-plane axes, with what is drawn on it besides the tool tips: the IMA's
// centerline (red) and outlines of the anatomy (fascia, fat, heart), each in its colour. A point p
// projects orthogonally to ((p - origin) . u, (p - origin) . v) in metres. The frame is written
// beside a recording as JSON so that tools pooling several recordings draw the same anatomy.
#include <array>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "math/types.hpp"

namespace imasim::metrics {

class HeatMapFrameError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct HeatMapOutline {
  std::string name;             // shown in the legend ("fascia")
  std::array<double, 3> rgb{};  // line colour, each in [0, 1]
  std::vector<Vec3> points;     // (unit: m)
  bool closed = true;           // a loop (the last point joins the first)
};

struct HeatMapFrame {
  Vec3 origin = Vec3::Zero();    // (unit: m)
  Vec3 u = Vec3::UnitX();        // along the IMA's course (drawn left to right)
  Vec3 v = Vec3::UnitY();        // across it (drawn bottom to top)
  std::vector<Vec3> centerline;  // the IMA's, in order (unit: m)
  std::vector<HeatMapOutline> outlines;
};

// In-plane coordinates (unit: m).
using PlanePoint = Eigen::Vector2d;

PlanePoint project(const HeatMapFrame& frame, const Vec3& p);
std::vector<PlanePoint> project(const HeatMapFrame& frame, std::span<const Vec3> points);

// Throws HeatMapFrameError, starting with `where`, when a number is not finite, u or v is not of
// unit length or they are not perpendicular (tolerance 1e-6), a colour is outside [0, 1] or an
// outline has no points.
void check_heat_map_frame(const HeatMapFrame& frame, const std::string& where);

// JSON text of the frame; the inverse refuses a malformed file naming the file and the key
// ("frame.json: key 'outlines[1].rgb': expected three numbers in [0, 1]").
std::string heat_map_frame_json(const HeatMapFrame& frame);
HeatMapFrame parse_heat_map_frame(const std::string& text, const std::string& path);

inline constexpr std::uint64_t kMaxHeatMapFrameBytes = std::uint64_t(64) << 20;  // 64 MiB

// Checked writes (metrics/output_file.hpp: OutputError naming the file; never over one of
// `inputs`) and a bounded read (HeatMapFrameError naming the file).
void write_heat_map_frame(const HeatMapFrame& frame, const std::string& path,
                          std::span<const std::string> inputs = {});
HeatMapFrame read_heat_map_frame(const std::string& path);

}  // namespace imasim::metrics
