#pragma once
// `imasim stats --a V1,V2,... --b V1,V2,... [--json]`: two groups compared as the study report
// compares the dynamic and static groups (metrics/statistics.hpp): mean_a, sd_a, mean_b, sd_b,
// t_welch, df_welch, p_welch, t_student, p_student, cohen_d.
#include <CLI/CLI.hpp>
#include <memory>
#include <vector>

namespace imasim::cli {

struct StatsOptions {
  std::vector<double> a, b;
  bool json = false;
};

std::shared_ptr<StatsOptions> add_stats_command(CLI::App& app);
int run_stats_command(const StatsOptions& options);

}  // namespace imasim::cli
