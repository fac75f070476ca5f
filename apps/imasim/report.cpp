#include "report.hpp"

#include <algorithm>
#include <iostream>

namespace imasim::cli {

double median(std::vector<double>& values) {
  if (values.empty()) return 0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

void add_status(nlohmann::ordered_json& out, bool positions_finite,
                const physics::StepResult& failure, std::uint64_t steps_done) {
  // A refused step leaves the state as it was before it, so positions stay finite; `finite`
  // says whether the simulation itself produced only finite values.
  out["finite"] = positions_finite && failure.status != physics::StepStatus::non_finite;
  out["status"] = physics::to_string(failure.status);
  if (!failure.ok()) {
    out["failed_step"] = steps_done;
    out["failed_particle"] = failure.particle;
  }
}

nlohmann::ordered_json profile_report(const physics::ProfileTotals& totals) {
  nlohmann::ordered_json stages = nlohmann::ordered_json::object();
  double sum = 0;
  for (std::size_t k = 0; k < physics::kStageCount; ++k) {
    const auto stage = static_cast<physics::Stage>(k);
    stages[physics::to_string(stage)] = 1e3 * totals.mean(stage);
    sum += 1e3 * totals.mean(stage);
  }
  stages["total"] = sum;
  return stages;
}

bool print_report(const nlohmann::ordered_json& out, bool json) {
  if (json) {
    std::cout << out.dump() << '\n';
  } else {
    for (const auto& [key, value] : out.items()) {
      std::cout << key << ": " << (value.is_string() ? value.get<std::string>() : value.dump())
                << '\n';
    }
  }
  std::cout.flush();
  return static_cast<bool>(std::cout);
}

}  // namespace imasim::cli
