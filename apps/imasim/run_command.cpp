#include "run_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "cli_checks.hpp"
#include "interrupt.hpp"
#include "math/state_hash.hpp"
#include "metrics/event_csv.hpp"
#include "report.hpp"
#include "run_progress.hpp"
#include "scene/scene_file.hpp"
#include "scene/solver_budget.hpp"
#include "scene/thorax_scene.hpp"
#include "session/surgical_session.hpp"
#include "session_report.hpp"
#include "surgery/input_script_repeat.hpp"
#include "tissue/mesh_object.hpp"

namespace imasim::cli {

namespace {

// The longest run: an hour of simulated time (a session lasts 10-30 minutes). Input scripts
// stop at the same time (docs/input_script.md).
constexpr double kMaxRunSeconds = 3600;
// The most steps of one run: an hour of 5 ms steps is 720,000; a step's time is kept (8 bytes).
constexpr double kMaxRunSteps = 4e6;
// As the scene file's anatomy.patient_seed (scene_keys.cpp).
// Runs estimated to take longer than this get a note on stderr before they start, with the cost
// of one particle sweep measured on the reference machine (docs/PERFORMANCE.md: 20-80 ns).
constexpr double kAnnouncedRunSeconds = 60;
constexpr double kSecondsPerParticleSweep = 30e-9;
constexpr std::uint64_t kMaxPatientSeed = 9'000'000'000'000'000'000u;

}  // namespace

std::shared_ptr<RunOptions> add_run_command(CLI::App& app) {
  auto opt = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Run the thorax scene (beating heart, tissues)");
  cmd->add_flag("--headless", opt->headless, "Run without a window (the only mode so far)");
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
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  cmd->add_flag("--progress", opt->progress,
                "Report the simulated time on stderr every few seconds (always on a terminal)");
  return opt;
}

int run_run_command(const RunOptions& o) {
  if (!o.headless) {
    std::cerr << "imasim run: the interactive window is not built yet; use --headless\n";
    return 2;
  }
  scene::ThoraxSceneParams params = scene::default_thorax_scene_params();
  if (!o.scene_file.empty()) {
    try {
      params = scene::load_scene_file(o.scene_file);
    } catch (const scene::SceneFileError& e) {
      for (const std::string& m : e.messages())
        std::cerr << m << '\n';
      return 2;
    }
  }
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
  if (!o.script_file.empty()) {
    try {
      script = surgery::load_input_script(o.script_file);
      if (o.repeat > 1) {
        script = surgery::repeat_input_script(*script, o.repeat, script->end_time() + 0.5);
      }
    } catch (const surgery::InputScriptError& e) {
      std::cerr << e.what() << '\n';
      return 2;
    }
  }
  if (o.repeat > 1 && !script) {
    std::cerr << "imasim run: --repeat needs --script (it repeats the script)\n";
    return 2;
  }
  std::optional<metrics::EventCsvWriter> events_out;
  if (!o.events_file.empty()) {
    if (!script) {
      std::cerr << "imasim run: --events needs --script (events come from the instruments)\n";
      return 2;
    }
    try {
      const std::string inputs[] = {o.scene_file, o.script_file};
      events_out.emplace(metrics::OutputFile(o.events_file, "the events file", inputs));
    } catch (const metrics::OutputError& e) {
      std::cerr << "imasim run: " << e.what() << '\n';
      return 2;
    }
  }
  std::optional<session::SurgicalSession> surgical;
  scene::ThoraxScene plain;
  try {
    if (script) {
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

  double seconds = o.seconds;
  if (script && o.seconds_option && o.seconds_option->count() == 0) {
    seconds = script->end_time() + 0.5;
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
  std::vector<double> step_ms;
  step_ms.reserve(steps);
  physics::StepResult failure;
  double ima_motion = 0;
  std::uint32_t max_contacts = 0;
  std::uint64_t missed_heart_contacts = 0;
  physics::ProfileTotals profile;
  std::uint64_t done = 0;
  std::optional<std::string> output_failure;
  install_interrupt_handlers();
  RunProgress progress("imasim run", seconds, double(w.model.solver.dt), o.progress, std::cerr);
  for (; done < steps && interrupt_signal() == 0; ++done) {
    const auto t0 = std::chrono::steady_clock::now();
    const physics::StepResult r =
        surgical
            ? session::step_session(*surgical, session::sample_script(*script, w.state.time), exec)
            : scene::step_thorax_scene(scene, exec);
    step_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (!r.ok()) {
      failure = r;
      break;
    }
    profile.add(r.profile);
    max_contacts = std::max(max_contacts, scene.heart.last_contacts);
    missed_heart_contacts += scene.missed_heart_contacts;
    for (std::uint32_t k = 0; k < ima.particle_count; ++k) {
      const std::uint32_t i = ima.first_particle + k;
      ima_motion = std::max(
          ima_motion,
          double((w.state.particles.position[i] - w.state.particles.rest_position[i]).norm()));
    }
    if (events_out) {
      try {
        events_out->append_new(surgical->events);
      } catch (const metrics::OutputError& e) {
        output_failure = e.what();
        ++done;
        break;
      }
    }
    progress.update(w.state.time);
  }
  progress.finish();
  // Whatever ended the run, the events recorded so far reach the file.
  if (events_out && !output_failure) {
    try {
      events_out->finish(surgical->events);
    } catch (const metrics::OutputError& e) {
      output_failure = e.what();
    }
  }
  const double median_ms = median(step_ms);
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
  out["ima_motion_max_m"] = ima_motion;
  out["heart_contacts_max"] = max_contacts;
  out["missed_heart_contacts"] = missed_heart_contacts;  // a warning: should stay 0
  out["ms_per_step_median"] = median_ms;
  out["profile_ms_per_step"] = profile_report(profile);  // mean per stage
  out["substeps"] = w.model.solver.substeps;
  out["iterations"] = w.model.solver.iterations;
  out["fascia_max_displacement_m"] = tissue::max_displacement(w, w.meshes[scene.patch.fascia]);
  out["vessel_max_displacement_m"] = tissue::max_displacement(w, ima);
  out["kinetic_energy_j"] = physics::kinetic_energy(w.state.particles);
  out["state_hash"] = to_hex(physics::position_hash(w.state));
  if (surgical) {
    out["script"] = o.script_file;
    add_session_report(out, *surgical);
    if (events_out) out["events_written"] = events_out->written();
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
