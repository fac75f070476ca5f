#include "trial_plan.hpp"

#include <cstdio>

namespace imasim::cli {

namespace {

constexpr std::uint64_t kPatientSalt = 0x70617469656e74ull;     // "patient"
constexpr std::uint64_t kOperatorSalt = 0x6f70657261746f72ull;  // "operator"
constexpr std::uint64_t kMaxSeed = 9'000'000'000'000'000'000u;  // --patient-seed's limit

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

std::string shortest(double v) {
  char out[32];
  std::snprintf(out, sizeof out, "%.17g", v);
  return out;
}

}  // namespace

std::uint64_t derived_seed(std::uint64_t study_seed, int trial, std::uint64_t salt) {
  const std::uint64_t mixed =
      splitmix64(splitmix64(study_seed ^ salt) + static_cast<std::uint64_t>(trial));
  return mixed % kMaxSeed + 1;
}

std::vector<TrialPlan> plan_trials(const std::vector<std::string>& modes, int trials,
                                   std::uint64_t study_seed, const std::string& dir) {
  const int width = trials >= 100 ? int(std::to_string(trials).size()) : 2;
  std::vector<TrialPlan> plans;
  for (const std::string& mode : modes) {
    for (int k = 1; k <= trials; ++k) {
      TrialPlan p;
      p.mode = mode;
      p.trial = k;
      p.patient_seed = derived_seed(study_seed, k, kPatientSalt);
      p.operator_seed = derived_seed(study_seed, k, kOperatorSalt);
      char number[24];
      std::snprintf(number, sizeof number, "%0*d", width, k);
      const std::string stem = dir + "/trials/" + mode + "-" + number;
      p.recording = stem + ".csv";
      p.side = stem + ".json";
      p.report = stem + ".report.json";
      p.log = stem + ".log";
      plans.push_back(p);
    }
  }
  return plans;
}

std::vector<std::string> trial_arguments(const TrialPlan& plan, const OperatorChoice& op) {
  std::vector<std::string> args = {"run",       "--headless", "--json",   "--study-trial",
                                   "--threads", "1",          "--record", plan.recording};
  if (plan.mode == "static") args.push_back("--static");
  args.insert(args.end(), {"--patient-seed", std::to_string(plan.patient_seed)});
  if (!op.script_file.empty())
    args.insert(args.end(), {"--script", op.script_file});
  else
    args.insert(args.end(), {"--autopilot", "--operator-seed", std::to_string(plan.operator_seed)});
  if (op.seconds) args.insert(args.end(), {"--seconds", shortest(*op.seconds)});
  if (op.no_db) {
    args.push_back("--no-db");
  } else {
    args.insert(args.end(), {"--trainee", op.trainee});
    if (!op.db.empty()) args.insert(args.end(), {"--db", op.db});
  }
  return args;
}

}  // namespace imasim::cli
