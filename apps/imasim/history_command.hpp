#pragma once
// `imasim history [--trainee NAME] [--db PATH] [--metric NAME] [--json]`: the trainees'
// progress over their recorded sessions (metrics/trainee_records.hpp), as a table per trainee
// with a progress line, or one JSON object (history_report.hpp; the keys are a contract).
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

namespace imasim::cli {

struct HistoryOptions {
  std::string trainee;  // empty: every trainee
  std::string db_file;  // empty: the default database (metrics/records_path.hpp)
  std::string metric;   // empty: no series
  bool json = false;
};

std::shared_ptr<HistoryOptions> add_history_command(CLI::App& app);

// Exit code: 0 shown, 2 a missing or unreadable database, an unknown trainee or metric, 4 stdout
// did not take the report.
int run_history_command(const HistoryOptions& options);

}  // namespace imasim::cli
