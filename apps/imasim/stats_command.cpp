#include "stats_command.hpp"

#include <iostream>
#include <nlohmann/json.hpp>

#include "metrics/statistics.hpp"
#include "report.hpp"

namespace imasim::cli {

std::shared_ptr<StatsOptions> add_stats_command(CLI::App& app) {
  auto opt = std::make_shared<StatsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "stats", "Compare two groups: mean and SD, Welch's and Student's t-tests, Cohen's d");
  cmd->add_option("--a", opt->a, "First group's values, comma-separated (at least two)")
      ->required()
      ->delimiter(',');
  cmd->add_option("--b", opt->b, "Second group's values, comma-separated (at least two)")
      ->required()
      ->delimiter(',');
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  return opt;
}

int run_stats_command(const StatsOptions& o) {
  metrics::TwoGroupComparison c;
  try {
    c = metrics::compare_groups(o.a, o.b);
  } catch (const metrics::StatisticsError& e) {
    std::cerr << "imasim stats: " << e.what() << '\n';
    return 2;
  }
  nlohmann::ordered_json out;
  out["mean_a"] = c.a.mean;
  out["sd_a"] = c.a.sd;
  out["mean_b"] = c.b.mean;
  out["sd_b"] = c.b.sd;
  out["t_welch"] = c.welch.t;
  out["df_welch"] = c.welch.df;
  out["p_welch"] = c.welch.p;
  out["t_student"] = c.student.t;
  out["p_student"] = c.student.p;
  out["cohen_d"] = c.cohen_d;
  return print_report(out, o.json) ? 0 : 4;
}

}  // namespace imasim::cli
