#pragma once
// `imasim heatmap --trajectory T.csv [--trajectory T2.csv ...] [--tool forceps|hook] --frame F.json
// --out P.png [--title TEXT] [--subtitle TEXT] [--bandwidth M] [--density-max D] [--width W
// --height H] [--json]`: the tool tips of one or more recordings (a study's group) pooled into
// one heat map as in Fig. 13 (metrics/heat_map.hpp), projected onto the frame a recording wrote
// (FILE.frame.json). T.csv is read as `imasim sai` reads it: the recorder's file with --tool, else
// a plain CSV with the header t,x,y,z (metres). Prints the picture's path, the samples, the
// recordings and the density at the top of the colour scale. Bad files: exit 2; an unwritable
// picture: exit 4.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

namespace imasim::cli {

struct HeatmapOptions {
  std::vector<std::string> trajectories;
  std::string tool, frame, out, title, subtitle;
  double bandwidth = 0.001;
  double density_max = 0;
  int width = 1100, height = 700;
  bool json = false;
};

std::shared_ptr<HeatmapOptions> add_heatmap_command(CLI::App& app);
int run_heatmap_command(const HeatmapOptions& options);

}  // namespace imasim::cli
