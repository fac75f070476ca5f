#pragma once
// One study's trials: which mode, which patient and operator seed, where each trial's files go,
// and the `imasim run` command line of each (trial_arguments: the one place it is built).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace imasim::cli {

// The trial's operator: an input script (with --script) or the scripted operator (autopilot).
struct OperatorChoice {
  std::string script_file;        // empty: the scripted operator
  std::optional<double> seconds;  // simulated time (unit: s); unset: the run's default
  // Where each scored trial is appended (the trainee records): a database, or the user's
  // default when empty; none with `no_db`. `trainee` names the operator in them.
  std::string db;
  bool no_db = false;
  std::string trainee = "scripted operator";
};

struct TrialPlan {
  std::string mode;  // "dynamic" or "static"
  int trial = 0;     // 1-based
  std::uint64_t patient_seed = 0;
  std::uint64_t operator_seed = 0;
  std::string recording;  // DIR/trials/<mode>-<NN>.csv (its side file: <mode>-<NN>.json)
  std::string side;       // DIR/trials/<mode>-<NN>.json
  std::string report;     // DIR/trials/<mode>-<NN>.report.json: the run's stdout
  std::string log;        // DIR/trials/<mode>-<NN>.log: the run's stderr
};

// A seed from the study's seed, the trial number and a salt (SplitMix64 of their mix), in
// [1, 9e18] (the range of --patient-seed, 0 excluded: 0 is the scene's own anatomy).
std::uint64_t derived_seed(std::uint64_t study_seed, int trial, std::uint64_t salt);

// `trials` per mode, mode by mode; trial k gets the same patient and operator seed in every
// mode (a paired design: only the heart differs). Files under `dir`/trials.
std::vector<TrialPlan> plan_trials(const std::vector<std::string>& modes, int trials,
                                   std::uint64_t study_seed, const std::string& dir);

// The arguments after the program's name: `run --headless --json --record CSV [--static]
// --patient-seed N`, the operator's: `--script FILE [--seconds T]`, or `--autopilot
// --operator-seed N [--seconds T]`, and the records': `--trainee NAME [--db PATH | --no-db]`.
std::vector<std::string> trial_arguments(const TrialPlan& plan, const OperatorChoice& op);

}  // namespace imasim::cli
