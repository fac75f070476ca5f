#pragma once
// Synthetic study results for the report's tests: the paper's Table 1 as the hook's SAI of ten
// dynamic and ten static trials, two metrics per trial, and a heat map drawn with cairo in
// colours a test can find again in pixels.
#include <cairo.h>

#include <string>
#include <vector>

#include "report/study_data.hpp"

namespace imasim::test {

inline const std::vector<double> kTable1Dynamic = {0.583, 0.621, 0.545, 0.602, 0.568,
                                                   0.634, 0.592, 0.551, 0.615, 0.577};
inline const std::vector<double> kTable1Static = {0.247, 0.268, 0.221, 0.285, 0.238,
                                                  0.276, 0.212, 0.257, 0.228, 0.243};

// The heat map's two colours (RGB, 0-255): a magenta band over a yellow one.
inline constexpr unsigned char kHeatLow[3] = {200, 30, 160};
inline constexpr unsigned char kHeatHigh[3] = {250, 220, 30};

// A 400 x 300 PNG: the top half kHeatLow, the bottom half kHeatHigh.
inline void write_heat_map_png(const std::string& path) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 400, 300);
  cairo_t* cr = cairo_create(s);
  cairo_set_source_rgb(cr, kHeatLow[0] / 255.0, kHeatLow[1] / 255.0, kHeatLow[2] / 255.0);
  cairo_rectangle(cr, 0, 0, 400, 150);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, kHeatHigh[0] / 255.0, kHeatHigh[1] / 255.0, kHeatHigh[2] / 255.0);
  cairo_rectangle(cr, 0, 150, 400, 150);
  cairo_fill(cr);
  cairo_destroy(cr);
  cairo_surface_write_to_png(s, path.c_str());
  cairo_surface_destroy(s);
}

inline report::TrialResult synthetic_trial(const std::string& mode, int number, double hook_sai) {
  report::TrialResult t;
  t.mode = mode;
  t.trial = number;
  t.patient_seed = 1000 + std::uint64_t(number);
  t.operator_seed = 2000 + std::uint64_t(number);
  t.ok = true;
  t.wall_s = 12.5;
  t.sai["hook"] = {hook_sai, 600, 0.004, 0.2};
  t.sai["forceps"] = {hook_sai / 2, 600, 0.006, 0.1};
  // time_to_complete_s: 100 s + the trial's number; heart_contacts: the trial's number mod 3,
  // which passes (<= 0) in trials 3, 6 and 9.
  t.metrics.push_back({"time_to_complete_s", "s", 100.0 + number, 600, false, true});
  t.metrics.push_back({"heart_contacts", "1", double(number % 3), 0, false, number % 3 == 0});
  return t;
}

// Table 1's twenty trials; with `heat_map` every trial's heat maps are that PNG.
inline std::vector<report::TrialResult> table1_trials(const std::string& heat_map = "") {
  std::vector<report::TrialResult> trials;
  for (int k = 0; k < 10; ++k)
    trials.push_back(synthetic_trial("dynamic", k + 1, kTable1Dynamic[std::size_t(k)]));
  for (int k = 0; k < 10; ++k)
    trials.push_back(synthetic_trial("static", k + 1, kTable1Static[std::size_t(k)]));
  if (!heat_map.empty())
    for (report::TrialResult& t : trials)
      t.heat_maps = {{"forceps", heat_map}, {"hook", heat_map}};
  return trials;
}

inline report::StudyInfo table1_info() {
  report::StudyInfo info;
  info.program = "imasim test";
  info.scene = "built-in thorax";
  info.modes = {"dynamic", "static"};
  info.trials_per_mode = 10;
  info.seed = 7;
  info.operator_kind = "autopilot";
  info.operator_description = "the scripted operator (autopilot)";
  info.jobs = 2;
  info.date = "2025-01-01 12:00 UTC";
  info.status = "complete";
  return info;
}

}  // namespace imasim::test
