#include "run_command.hpp"
#include "command_inputs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli_checks.hpp"
#include "console/console_settings_use.hpp"
#include "console/input_stream.hpp"
#include "console/stream_origin.hpp"
#include "interrupt.hpp"
#include "live_inputs.hpp"
#include "math/state_hash.hpp"
#include "metrics/event_csv.hpp"
#include "metrics/threshold_file.hpp"
#include "replay_origin.hpp"
#include "report.hpp"
#include "run_progress.hpp"
#include "run_recording.hpp"
#include "run_trainee_record.hpp"
#include "run_watch.hpp"
#include "runner/event_csv_observer.hpp"
#include "runner/input_stream_recorder.hpp"
#include "runner/session_runner.hpp"
#include "scene/scene_file.hpp"
#include "scene/solver_budget.hpp"
#include "scene/thorax_scene.hpp"
#include "session/surgical_session.hpp"
#include "session_report.hpp"
#include "surgery/input_script_repeat.hpp"
#include "tissue/mesh_object.hpp"

namespace imasim::cli {

namespace {

// What the recording's side file says was run.
nlohmann::ordered_json recording_info(const RunOptions& o, const scene::ThoraxSceneParams& params,
                                      const session::SurgicalSession& s, const std::string& devices,
                                      bool replay) {
  nlohmann::ordered_json j;
  j["program"] = "imasim " IMASIM_VERSION;
  j["scene"] = o.scene_file.empty() ? std::string("built-in thorax") : o.scene_file;
  j["patient_seed"] = s.scene.patient.patient_seed;
  j["heart"] = params.playback.beating ? "dynamic" : "static";
  j["heart_rate_bpm"] = params.playback.heart_rate_bpm;
  j["input"] = replay ? "replay" : devices;
  if (!o.script_file.empty()) j["script"] = o.script_file;
  if (replay) j["replay"] = o.replay_file;
  const physics::SolverParams& solver = s.scene.patch.world.model.solver;
  j["dt_s"] = solver.dt;
  j["substeps"] = solver.substeps;
  j["iterations"] = solver.iterations;
  return j;
}

// The longest run: an hour of simulated time (a session lasts 10-30 minutes). Input scripts
// stop at the same time (docs/input_script.md).
constexpr double kMaxRunSeconds = 3600;
// The most steps of one run: an hour of 5 ms steps is 720,000; a step's time is kept (8 bytes).
constexpr double kMaxRunSteps = 4e6;
// As the scene file's anatomy.patient_seed (scene_keys.cpp).
// Runs estimated to take longer than this get a note on stderr before they start, with the cost
// of one particle sweep measured on the reference machine (docs/PERFORMANCE.md: 14-106 ns).
constexpr double kAnnouncedRunSeconds = 60;
constexpr double kSecondsPerParticleSweep = 30e-9;
constexpr std::uint64_t kMaxPatientSeed = 9'000'000'000'000'000'000u;

// A mesh's solver in run's JSON ("xpbd" or "implicit"), and the implicit one's Newton counts:
// steps left above the tolerance, the largest residual, per step its iterations and
// factorisations (and why: the held vertices changed; the rest the kept matrix converged too
// slowly), the Newton steps the line search cut short, the rebuilds after a cut.
void add_implicit_report(nlohmann::ordered_json& out, const std::string& name,
                         const std::optional<scene::SceneImplicitMesh>& mesh) {
  out[name + "_solver"] = mesh ? "implicit" : "xpbd";
  if (!mesh) return;
  const scene::SceneImplicitMesh& f = *mesh;
  const double steps = double(std::max<std::uint64_t>(f.steps, 1));
  out[name + "_unsolved_steps"] = f.unsolved_steps;
  out[name + "_largest_residual_n"] = f.largest_residual;
  out[name + "_newton_iterations_per_step"] = double(f.iterations) / steps;
  out[name + "_factorizations_per_step"] = double(f.factorizations) / steps;
  out[name + "_active_set_factorizations_per_step"] = double(f.active_set_factorizations) / steps;
  out[name + "_shortened_iterations_per_step"] = double(f.shortened_iterations) / steps;
  out[name + "_refits"] = f.refits;
}

}  // namespace

std::shared_ptr<RunOptions> add_run_command(CLI::App& app) {
  auto opt = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Run the thorax scene (beating heart, tissues)");
  cmd->add_flag("--headless", opt->headless, "Run without a window (see `imasim window`)");
  cmd->add_option("--scene", opt->scene_file, "Scene file (TOML); default: the built-in scene")
      ->check(non_empty());
  opt->seconds_option =
      cmd->add_option("--seconds", opt->seconds,
                      "Simulated time (s); with --script, default: the script's end + 0.5 s")
          ->capture_default_str()
          ->check(finite_range(0.0, kMaxRunSeconds));
  cmd->add_option("--script", opt->script_file,
                  "Input script driving the instruments (docs/input_script.md)")
      ->check(non_empty());
  cmd->add_option("--repeat", opt->repeat,
                  "Play the script this many times in a row, one cycle every (its end + 0.5 s)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--events", opt->events_file, "Write the session's events to this CSV file")
      ->check(non_empty());
  cmd->add_option("--record", opt->record_file,
                  "Record the session at 60 Hz: FILE.csv (tool tips, jaws, device poses, forces, "
                  "pedal), FILE.json (what was run, the columns' units) and FILE.events.csv "
                  "(unless --events names another file); docs/scoring.md")
      ->check(non_empty());
  cmd->add_option("--thresholds", opt->thresholds_file,
                  "With --record: proficiency thresholds, a JSON object of metric name to "
                  "threshold, replacing the defaults (docs/scoring.md)")
      ->check(non_empty());
  cmd->add_option("--trainee", opt->trainee,
                  "With --record: the trainee the session is recorded for (default: $USER, else "
                  "anonymous; at most 64 characters of printable text)")
      ->check(trainee_name());
  CLI::Option* db =
      cmd->add_option("--db", opt->db_file,
                      "With --record: the trainee records (SQLite) to append the scored session "
                      "to; default: $XDG_DATA_HOME/imasim/trainees.sqlite, else "
                      "~/.local/share/imasim/trainees.sqlite")
          ->check(non_empty());
  cmd->add_flag("--no-db", opt->no_db, "With --record: append no trainee record")->excludes(db);
  cmd->add_flag("--static", opt->static_heart, "Freeze the heart at its static phase (70 %)");
  cmd->add_option("--heart-rate", opt->heart_rate_bpm,
                  "Heart rate (beats per minute); default: the scene's (75)")
      ->check(finite_range(20.0, 250.0));
  // The scene file's anatomy.patient_seed takes the same range.
  cmd->add_option("--patient-seed", opt->patient_seed,
                  "Virtual patient: 0 = the scene's anatomy, else a seeded variation of it")
      ->check(unsigned_at_most(kMaxPatientSeed));
  const auto sweeps = static_cast<std::uint32_t>(scene::kMaxSweepsPerStep);
  cmd->add_option("--substeps", opt->substeps,
                  "Solver substeps per 5 ms step; default: the scene's")
      ->check(CLI::Range(1u, sweeps));
  cmd->add_option("--iterations", opt->iterations,
                  "Projection sweeps per substep; default: the scene's")
      ->check(CLI::Range(1u, sweeps));
  cmd->add_option("--threads", opt->threads, "Worker threads (0 = all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--devices", opt->devices,
                  "Input: script (the --script file), openigtlink (live devices, real time, "
                  "1 kHz force feedback), emulator (two emulated haptic devices playing "
                  "--script over OpenIGTLink), gamepad (SDL2), spacemouse (spacenavd), "
                  "openhaptics or force_dimension (vendor SDKs, when built with them); "
                  "`imasim devices` lists them")
      ->check(CLI::IsMember({"script", "openigtlink", "emulator", "gamepad", "spacemouse",
                             "openhaptics", "force_dimension"}));
  cmd->add_option("--replay", opt->replay_file,
                  "Replay a recorded input stream (--record-input) step by step")
      ->check(non_empty());
  cmd->add_flag("--study-trial", opt->study_trial,
                "(experiment's) an interrupted run leaves the trainee records alone: the study's "
                "rerun records the trial")
      ->group("");  // hidden: the study's own
  cmd->add_flag("--replay-anyway", opt->replay_anyway,
                "Replay a stream recorded under another program, scene, patient, heart mode or "
                "solver, or one cut short (said on stderr); its state will differ");
  cmd->add_option("--record-input", opt->record_input_file,
                  "Write every step's input here (replayable with --replay)")
      ->check(non_empty());
  cmd->add_option("--igtl-address", opt->igtl_address,
                  "OpenIGTLink: where to listen, or with --igtl-client whom to call; default: "
                  "the scene's devices.igtl_address (loopback only unless the scene file allows "
                  "more)")
      ->check(non_empty());
  cmd->add_option("--igtl-port", opt->igtl_port,
                  "OpenIGTLink port (0: any free); default: the scene's devices.igtl_port")
      ->check(CLI::Range(0, 65535));
  cmd->add_flag("--igtl-client", opt->igtl_client,
                "OpenIGTLink: call a tracker's server instead of listening");
  cmd->add_flag("--pedal", opt->pedal,
                "With live --devices: foot pedals from a joystick's buttons (a USB foot "
                "switch), mapped by the scene's devices.pedal_* keys");
  add_autopilot_options(*cmd, opt->autopilot);
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  cmd->add_flag("--progress", opt->progress,
                "Report the simulated time on stderr every few seconds (always on a terminal)");
  return opt;
}

int run_run_command(const RunOptions& o) {
  if (!o.headless) {
    std::cerr << "imasim run: needs --headless (the window is `imasim window`)\n";
    return 2;
  }
  scene::ThoraxSceneParams params;
  if (!load_scene_params(o.scene_file, params)) return 2;
  // The command line overrides the file where given.
  if (o.static_heart) params.playback.beating = false;
  if (o.heart_rate_bpm > 0) params.playback.heart_rate_bpm = Real(o.heart_rate_bpm);
  if (o.patient_seed) params.anatomy.patient_seed = *o.patient_seed;
  if (o.substeps > 0) params.patch.solver.substeps = o.substeps;
  if (o.iterations > 0) params.patch.solver.iterations = o.iterations;
  if (const std::string problem = scene::solver_budget_problem(
          scene::estimate_thorax_particles(params), params.patch.solver.substeps,
          params.patch.solver.iterations, "substeps x iterations");
      !problem.empty()) {
    std::cerr << "imasim run: " << problem << '\n';
    return 2;
  }
  std::optional<surgery::InputScript> script;
  if (!load_script(o.script_file, script)) return 2;
  if (script && o.repeat > 1) {
    try {
      script = surgery::repeat_input_script(*script, o.repeat, script->end_time() + 0.5);
    } catch (const surgery::InputScriptError& e) {
      std::cerr << e.what() << '\n';
      return 2;
    }
  }
  if (o.autopilot.enabled && (script || !o.devices.empty() || !o.replay_file.empty())) {
    std::cerr << "imasim run: --autopilot drives the instruments itself; it takes no --script, "
                 "--devices or --replay\n";
    return 2;
  }
  const std::string devices = !o.devices.empty()    ? o.devices
                              : script              ? "script"
                              : o.autopilot.enabled ? "autopilot"
                                                    : "";
  const bool live = !devices.empty() && devices != "script" && devices != "autopilot";
  if (!o.replay_file.empty() && (script || !o.devices.empty())) {
    std::cerr << "imasim run: --replay plays a recorded stream; it takes no --script or "
                 "--devices\n";
    return 2;
  }
  if ((devices == "script" || devices == "emulator") && !script) {
    std::cerr << "imasim run: --devices " << devices << " needs --script (the path to play)\n";
    return 2;
  }
  if (live && devices != "emulator" && script) {
    std::cerr << "imasim run: --devices " << devices
              << " takes its input from the devices, not --script\n";
    return 2;
  }
  if (o.pedal && !live) {
    std::cerr << "imasim run: --pedal goes with live --devices (openigtlink, emulator, gamepad, "
                 "spacemouse, ...)\n";
    return 2;
  }
  if (o.replay_anyway && o.replay_file.empty()) {
    std::cerr << "imasim run: --replay-anyway goes with --replay\n";
    return 2;
  }
  const console::StreamOrigin origin = console::stream_origin_of(params, IMASIM_VERSION);
  std::optional<std::vector<session::SessionInput>> replay;
  if (!o.replay_file.empty()) {
    try {
      console::RecordedStream recorded = console::load_recorded_stream(o.replay_file);
      const ReplayVerdict verdict = check_replay(recorded, o.replay_file, origin, o.replay_anyway);
      for (const std::string& line : verdict.lines)
        std::cerr << "imasim run: " << line << '\n';
      if (verdict.refused) return 2;
      replay = std::move(recorded.steps);
    } catch (const console::InputStreamError& e) {
      std::cerr << e.what() << '\n';
      return 2;
    }
  }
  const bool instruments = script || replay || live || o.autopilot.enabled;
  if (o.repeat > 1 && !script) {
    std::cerr << "imasim run: --repeat needs --script (it repeats the script)\n";
    return 2;
  }
  if (!o.record_file.empty() && !instruments) {
    std::cerr << "imasim run: --record needs instruments (--script, --devices or --replay)\n";
    return 2;
  }
  std::map<std::string, double> thresholds;
  if (!o.thresholds_file.empty()) {
    if (o.record_file.empty()) {
      std::cerr << "imasim run: --thresholds goes with --record (they score the recording)\n";
      return 2;
    }
    try {
      thresholds = metrics::load_threshold_file(o.thresholds_file);
    } catch (const metrics::ThresholdFileError& e) {
      std::cerr << e.what() << '\n';
      return 2;
    }
  }
  if (o.record_file.empty() && (!o.trainee.empty() || !o.db_file.empty() || o.no_db)) {
    std::cerr << "imasim run: --trainee, --db and --no-db go with --record (they keep its "
                 "scores)\n";
    return 2;
  }
  std::optional<metrics::TraineeRecords> records;
  std::string trainee;
  const std::string started_utc = metrics::utc_timestamp();
  if (!o.record_file.empty() && !o.no_db) {
    try {
      const RecordsChoice choice = choose_records(o.trainee, o.db_file);
      trainee = choice.trainee;
      records.emplace(choice.database, metrics::TraineeRecords::Access::append);
      for (const std::string& note : records->notes())
        std::cerr << "imasim run: " << note << '\n';
    } catch (const metrics::RecordsError& e) {
      std::cerr << "imasim run: " << e.what() << '\n';
      return 2;
    }
  }
  const std::string events_file = !o.events_file.empty() ? o.events_file
                                  : !o.record_file.empty()
                                      ? RunRecording::events_path_of(o.record_file)
                                      : std::string();
  std::optional<runner::EventCsvObserver> events_out;
  if (!events_file.empty()) {
    if (!instruments) {
      std::cerr << "imasim run: --events needs instruments (--script, --devices or --replay)\n";
      return 2;
    }
    try {
      const std::string inputs[] = {o.scene_file, o.script_file, o.replay_file};
      events_out.emplace(
          metrics::EventCsvWriter(metrics::OutputFile(events_file, "the events file", inputs)));
    } catch (const metrics::OutputError& e) {
      std::cerr << "imasim run: " << e.what() << '\n';
      return 2;
    }
  }
  std::optional<runner::InputStreamRecorder> record_out;
  if (!o.record_input_file.empty()) {
    if (!instruments) {
      std::cerr << "imasim run: --record-input needs instruments (--script, --devices or "
                   "--replay)\n";
      return 2;
    }
    try {
      const std::string inputs[] = {o.scene_file, o.script_file, o.replay_file, events_file};
      record_out.emplace(metrics::OutputFile(o.record_input_file, "the input stream", inputs),
                         origin);
    } catch (const metrics::OutputError& e) {
      std::cerr << "imasim run: " << e.what() << '\n';
      return 2;
    }
  }
  std::optional<session::SurgicalSession> surgical;
  scene::ThoraxScene plain;
  try {
    if (instruments) {
      surgical = session::make_surgical_session(params, session::SessionParams{});
    } else {
      plain = scene::make_thorax_scene(params);
    }
  } catch (const std::exception& e) {
    std::cerr << "imasim run: cannot build the scene: " << e.what() << '\n';
    return 2;
  }
  scene::ThoraxScene& scene = surgical ? surgical->scene : plain;
  for (const std::string& note : scene.setup_notes)
    std::cerr << "imasim run: note: " << note << '\n';
  physics::Executor exec(o.threads);
  tissue::TissueWorld& w = scene.patch.world;
  const tissue::MeshObject& ima = w.meshes[scene.patch.ima];

  std::optional<RunAutopilot> autopilot;
  if (o.autopilot.enabled) {
    try {
      autopilot.emplace(*surgical, o.autopilot.params);
    } catch (const std::invalid_argument& e) {
      std::cerr << "imasim run: the scripted operator cannot plan in this scene: " << e.what()
                << '\n';
      return 2;
    }
  }

  std::optional<RunRecording> recording;
  if (!o.record_file.empty()) {
    try {
      const std::string inputs[] = {o.scene_file, o.script_file,       o.replay_file,
                                    events_file,  o.record_input_file, o.thresholds_file};
      recording.emplace(o.record_file, inputs, console::force_model_params(params.console),
                        recording_info(o, params, *surgical, devices, replay.has_value()),
                        *surgical, params.patch.vessel.radius, thresholds);
      recording->sample(*surgical);  // the state before the first step
    } catch (const metrics::OutputError& e) {
      std::cerr << "imasim run: " << e.what() << '\n';
      return 2;
    } catch (const metrics::SaiError& e) {
      std::cerr << "imasim run: cannot score this scene: " << e.what() << '\n';
      return 2;
    }
  }

  double seconds = o.seconds;
  const bool seconds_given = o.seconds_option && o.seconds_option->count() > 0;
  if (script && !seconds_given) seconds = script->end_time() + 0.5;
  if (autopilot && !seconds_given) seconds = autopilot->end_time() + 0.5;
  if (replay) {
    const double recorded = double(replay->size()) * double(w.model.solver.dt);
    if (seconds_given && seconds > recorded + 0.5 * double(w.model.solver.dt)) {
      std::cerr << "imasim run: " << o.replay_file << " holds " << recorded << " s ("
                << replay->size() << " steps); --seconds " << seconds << " asks for more\n";
      return 2;
    }
    seconds = seconds_given ? seconds : recorded;
  }
  std::unique_ptr<LiveInputs> live_inputs;
  if (live) {
    LiveInputOptions lo;
    lo.devices = devices;
    lo.script_file = o.script_file;
    lo.scene_file = o.scene_file;
    lo.settings = params.console;
    lo.address = o.igtl_address;
    lo.port = o.igtl_port;
    if (devices == "emulator" && !o.igtl_port) lo.port = 0;  // any free port, told to the child
    lo.client = o.igtl_client;
    lo.pedal = o.pedal;
    try {
      live_inputs = std::make_unique<LiveInputs>(lo);
    } catch (const std::exception& e) {
      std::cerr << "imasim run: " << e.what() << '\n';
      return 2;
    }
  }
  // Each step keeps its time for the median: bounded, so that a tiny solver.dt_s cannot ask for
  // more than memory holds.
  if (const double wanted = seconds / double(w.model.solver.dt); !(wanted <= kMaxRunSteps)) {
    std::cerr << "imasim run: " << seconds << " s at solver.dt_s = " << w.model.solver.dt
              << " s is " << wanted << " steps, above the limit of " << kMaxRunSteps
              << ": run shorter or with a longer step\n";
    return 2;
  }
  // A long run says so up front instead of appearing to hang (estimated, not measured).
  const double estimate_s = std::ceil(seconds / double(w.model.solver.dt)) *
                            kSecondsPerParticleSweep *
                            double(scene::estimate_thorax_particles(params)) *
                            double(w.model.solver.substeps * w.model.solver.iterations);
  if (estimate_s > kAnnouncedRunSeconds) {
    std::cerr << "imasim run: note: this run may take about " << std::llround(estimate_s / 60)
              << " min (" << seconds << " s simulated; fewer --seconds, --substeps or "
              << "--iterations run faster)\n";
  }
  const auto steps = static_cast<std::uint64_t>(std::llround(seconds / double(w.model.solver.dt)));
  install_interrupt_handlers();
  RunProgress progress("imasim run", seconds, double(w.model.solver.dt), o.progress, std::cerr);
  RunWatch watch(scene, progress, steps);
  physics::StepResult failure;
  std::uint64_t done = 0;
  std::optional<std::string> output_failure;
  if (surgical) {
    // The session's steps through the one runner: its input, then its observers in order.
    std::optional<runner::ScriptInput> script_input;
    std::optional<runner::ReplayInput> replay_input;
    runner::InputSource* source = live_inputs.get();
    if (!source && replay) source = &replay_input.emplace(std::move(*replay));
    if (!source && script) source = &script_input.emplace(*script);
    if (!source) source = &*autopilot;
    runner::SessionRunner run(
        *surgical, *source, exec,
        live_inputs ? runner::Pacing::real_time : runner::Pacing::as_fast_as_possible);
    run.observe(watch);
    if (record_out) run.observe(*record_out);
    if (recording) run.observe(*recording);
    if (events_out) run.observe(*events_out);
    const runner::RunOutcome outcome = run.run(steps, [] { return interrupt_signal() != 0; });
    done = outcome.steps;
    failure = outcome.failure;
    if (!outcome.output_error.empty()) output_failure = outcome.output_error;
  } else {
    // The scene alone (no instruments): nothing to take input from or record.
    for (; done < steps && interrupt_signal() == 0; ++done) {
      const auto t0 = std::chrono::steady_clock::now();
      const physics::StepResult r = scene::step_thorax_scene(scene, exec);
      if (!r.ok()) {
        failure = r;
        break;
      }
      watch.watch(
          r,
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  progress.finish();
  nlohmann::ordered_json device_report;
  if (live_inputs) device_report = live_inputs->finish();
  const double median_ms = watch.median_ms();
  bool finite = true;
  for (const Vec3& x : w.state.particles.position)
    finite = finite && x.allFinite();

  nlohmann::ordered_json out;
  out["scene"] = o.scene_file.empty() ? std::string("built-in thorax") : o.scene_file;
  out["heart"] = params.playback.beating ? "beating" : "static";
  out["heart_rate_bpm"] = params.playback.heart_rate_bpm;
  out["heart_source"] = params.heart_series.phase_files.empty() ? "procedural" : "phase files";
  out["setup_notes"] = scene.setup_notes;
  out["patient_seed"] = scene.patient.patient_seed;
  out["ima_depth_m"] = scene.patient.ima_depth;
  out["ima_lateral_offset_m"] = scene.patient.ima_lateral_offset;
  out["skeleton_meshes"] = scene.skeleton.size();
  out["particles"] = w.state.particles.size();
  out["distance_constraints"] = w.state.constraints.distance.size();
  out["dihedral_constraints"] = w.state.constraints.dihedral.size();
  out["strands"] =
      w.strands[scene.patch.ima_fat].strand_count + w.strands[scene.patch.fascia_fat].strand_count;
  out["ports"] = scene.ports.size();
  out["threads"] = exec.threads();
  out["steps"] = done;
  out["simulated_s"] = w.state.time;
  out["heart_phase"] = scene.heart.phase;
  out["ima_motion_max_m"] = watch.ima_motion();
  // The ribs and the wall's surface over the run (bone: should stay 0).
  out["chest_wall_motion_max_m"] = watch.chest_wall_motion();
  out["heart_contacts_max"] = watch.max_contacts();
  out["missed_heart_contacts"] = watch.missed_heart_contacts();  // a warning: should stay 0
  // Each mesh's solver, and with the implicit one the steps whose Newton solve ran out of
  // iterations above its tolerance (a warning: rare buckling of slack fascia).
  add_implicit_report(out, "fascia", scene.implicit_fascia);
  add_implicit_report(out, "vessel", scene.implicit_vessel);
  out["ms_per_step_median"] = median_ms;
  out["profile_ms_per_step"] = profile_report(watch.profile());  // mean per stage
  out["substeps"] = w.model.solver.substeps;
  out["iterations"] = w.model.solver.iterations;
  out["fascia_max_displacement_m"] = tissue::max_displacement(w, w.meshes[scene.patch.fascia]);
  out["vessel_max_displacement_m"] = tissue::max_displacement(w, ima);
  out["kinetic_energy_j"] = physics::kinetic_energy(w.state.particles);
  out["state_hash"] = to_hex(physics::position_hash(w.state));
  if (surgical) {
    out["input"] = replay ? "replay" : devices;
    out["script"] = o.script_file;
    if (replay) out["replay"] = o.replay_file;
    if (record_out) out["input_recorded"] = o.record_input_file;
    if (live_inputs) out["devices"] = device_report;
    if (autopilot) out["operator"] = autopilot->report(*surgical);
    add_session_report(out, *surgical);
    if (events_out) out["events_written"] = events_out->writer().written();
  }
  add_status(out, finite, failure, done);
  if (const int signal = interrupt_signal(); signal != 0) {
    out["status"] = "interrupted";
    out["signal"] = signal;
  }
  if (output_failure) {
    out["status"] = "output_failed";
    out["output_error"] = *output_failure;
  }
  if (recording) {
    try {
      out["scores"] = recording->finish(
          {{"status", out["status"]}, {"steps", done}, {"simulated_s", w.state.time}}, *surgical);
      out["recorded"] = o.record_file;
      out["recorded_rows"] = recording->rows();
      if (records && o.study_trial && interrupt_signal() != 0) {
        out["trainee_record"] = {
            {"skipped",
             "an interrupted trial of a study: recorded when the study's rerun runs it"}};
      } else if (records) {
        metrics::SessionRecord session;
        session.trainee = trainee;
        session.date_utc = started_utc;
        session.scene = out["scene"].get<std::string>();
        session.heart = params.playback.beating ? metrics::HeartMode::dynamic
                                                : metrics::HeartMode::static_heart;
        session.patient_seed = scene.patient.patient_seed;
        session.operator_kind = operator_kind_of(devices, replay.has_value());
        session.input = replay ? "replay" : devices;
        session.status = out["status"].get<std::string>();
        session.recording = std::filesystem::absolute(o.record_file).string();
        out["trainee_record"] = append_trainee_record(*records, *recording, session);
        if (out["trainee_record"].contains("pending"))
          std::cerr << "imasim run: the trainee records stayed locked by another process for "
                    << metrics::kRecordsAppendWaitMs / 1000 << " s: this session is held in "
                    << out["trainee_record"]["pending"].get<std::string>()
                    << " and is added with the next recorded run\n";
      }
    } catch (const std::runtime_error& e) {  // OutputError, RecordsError
      if (!output_failure) output_failure = e.what();
      out["status"] = "output_failed";
      out["output_error"] = *output_failure;
    }
  }
  if (!print_report(out, o.json)) {
    std::cerr << "imasim run: cannot write the report to stdout\n";
    return 4;
  }
  if (output_failure) {
    std::cerr << "imasim run: " << *output_failure << '\n';
    return 4;
  }
  if (const int signal = interrupt_signal(); signal != 0) return interrupted_exit_status(signal);
  return failure.ok() ? 0 : 3;
}

}  // namespace imasim::cli
