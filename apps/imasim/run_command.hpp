#pragma once
// `imasim run --headless`: assembles the thorax scene (tissues, beating heart, ports), steps it
// (or, with --script, a surgical session driven by an input script) and reports timings, the heart
// phase, the motion reaching the IMA, a state hash and any divergence.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "run_autopilot.hpp"

namespace imasim::cli {

struct RunOptions {
  bool headless = false;
  std::string scene_file;  // empty: the built-in scene
  double seconds = 5;
  bool static_heart = false;
  double heart_rate_bpm = 0;                  // 0: the scene's
  std::optional<std::uint64_t> patient_seed;  // unset: the scene's
  int threads = 0;
  std::uint32_t substeps = 0;    // 0: the scene's
  std::uint32_t iterations = 0;  // 0: the scene's
  bool json = false;
  bool progress = false;     // progress lines on stderr even when it is not a terminal
  std::string script_file;   // empty: no instruments; else a surgical session driven by it
  std::uint32_t repeat = 1;  // plays of the script in a row
  std::string events_file;   // empty: events only counted; else written there as CSV
  // Where the instruments' input comes from (live_inputs.hpp): "" (the script if any),
  // "script", "openigtlink" or "emulator"; or a recorded stream to replay.
  std::string devices;
  std::string replay_file;
  bool replay_anyway = false;  // play a stream of another origin, or one cut short
  // A trial of a study (experiment passes it): interrupted, it leaves the trainee records alone,
  // for the study's rerun runs it again and records it then (once per trial).
  bool study_trial = false;
  std::string record_input_file;  // empty: not recorded; else every step's input written there
  std::string record_file;        // empty: no trajectory; else the 60 Hz recording (CSV + JSON)
  std::string thresholds_file;    // empty: the metrics' default thresholds
  // With record_file: the trainee records (run_trainee_record.hpp).
  std::string trainee;                      // empty: $USER, else "anonymous"
  std::string db_file;                      // empty: the user's data directory
  bool no_db = false;                       // no trainee record
  std::optional<std::string> igtl_address;  // unset: the scene file's (devices.igtl_address)
  std::optional<std::uint16_t> igtl_port;   // unset: the scene file's (devices.igtl_port)
  bool igtl_client = false;
  bool pedal = false;  // a foot switch (a joystick's buttons) drives the pedals and the clutch
  AutopilotOptions autopilot;             // the scripted operator drives the instruments
  CLI::Option* seconds_option = nullptr;  // given on the command line?
};

std::shared_ptr<RunOptions> add_run_command(CLI::App& app);

// Returns the exit code: 0 ok, 2 bad request, 3 the simulation refused a step, 4 an output could
// not be written, 128 + signal when SIGINT, SIGTERM or SIGHUP ended the run (its outputs and
// report are complete up to the step it stopped at).
int run_run_command(const RunOptions& options);

}  // namespace imasim::cli
