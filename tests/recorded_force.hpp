#pragma once
// A scripted run of `imasim run` with a [solver] table, and one column of its 60 Hz record: the
// session-level convergence checks (hook_press_test.cpp, grasp_pull_test.cpp) compare the force
// a hand feels at the default solver settings with finer ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_process.hpp"

namespace imasim::test {

struct RecordedColumn {
  std::vector<double> t, value;  // (unit: s, the column's)

  // The mean over [from, to) (0 with no sample there) and how many samples it took.
  double mean(double from, double to, std::size_t* samples = nullptr) const {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (t[k] < from || t[k] >= to) continue;
      sum += value[k];
      ++n;
    }
    if (samples != nullptr) *samples = n;
    return n > 0 ? sum / double(n) : 0;
  }
};

// Column `name` of a run's record, with its times (t_s). Values are read whole (9.8e-14 is not
// 9.8).
inline RecordedColumn recorded_column(const std::string& csv, const std::string& name) {
  std::istringstream text(read_file(csv));
  std::string line;
  std::getline(text, line);
  std::vector<std::string> header;
  {
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');)
      header.push_back(cell);
  }
  const auto column = [&](const std::string& key) {
    return std::size_t(std::find(header.begin(), header.end(), key) - header.begin());
  };
  const std::size_t t_col = column("t_s"), v_col = column(name);
  EXPECT_LT(v_col, header.size()) << csv << " has no " << name;
  RecordedColumn out;
  while (std::getline(text, line)) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');)
      cells.push_back(cell);
    if (cells.size() != header.size() || v_col >= header.size()) continue;
    out.t.push_back(std::stod(cells[t_col]));
    out.value.push_back(std::stod(cells[v_col]));
  }
  return out;
}

#ifdef IMASIM_EXE
// `imasim run` on `script` for `seconds` with the scene file `solver` ("" for the defaults),
// recorded; returns the record's column `name`. Files go to `directory` under `stem`.
inline RecordedColumn run_recorded(const std::string& directory, const std::string& stem,
                                   const std::string& solver, const std::string& script,
                                   const std::string& seconds, const std::string& name) {
  const std::string scene = directory + stem + ".toml";
  std::ofstream(scene) << solver;
  const std::string csv = directory + stem + ".csv";
  const std::string err = test_err_file(directory, stem);
  const Finished f =
      run_imasim("run --headless --scene " + scene + " --script " + script + " --seconds " +
                     seconds + " --threads 1 --no-db --record " + csv,
                 err);
  EXPECT_EQ(f.exit_code, 0) << f.err;
  return recorded_column(csv, name);
}
#endif

}  // namespace imasim::test
