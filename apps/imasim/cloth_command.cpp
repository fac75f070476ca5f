#include "cloth_command.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "interrupt.hpp"
#include "math/state_hash.hpp"
#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "report.hpp"
#include "run_progress.hpp"

namespace imasim::cli {

std::shared_ptr<ClothOptions> add_cloth_command(CLI::App& app) {
  auto opt = std::make_shared<ClothOptions>();
  scene::ClothParams& p = opt->params;
  CLI::App* cmd = app.add_subcommand("cloth", "Run the cloth verification scene");
  cmd->add_option("--n", p.n, "Vertices per side")
      ->capture_default_str()
      ->check(CLI::Range(3, 4096));  // n^2 is also held to the solver budget (make_cloth_scene)
  cmd->add_option("--size", p.size, "Side length L (m)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--mass", p.mass, "Total mass M (kg)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--steps", opt->steps, "Steps to run")
      ->capture_default_str()
      ->check(CLI::Range(0u, 100000000u));
  cmd->add_option("--dt", p.dt, "Step (s)")->capture_default_str()->check(CLI::Range(1e-6, 1.0));
  // The cloth's colour passes cost about 0.2 ms a sweep at any size: 64 x 64 sweeps over the
  // default 400 steps take minutes already (the verification runs use 1-5).
  constexpr std::uint32_t sweeps = 64;
  cmd->add_option("--iterations", p.iterations, "Projection sweeps per substep")
      ->capture_default_str()
      ->check(CLI::Range(1u, sweeps));
  cmd->add_option("--substeps", p.substeps, "Substeps per step")
      ->capture_default_str()
      ->check(CLI::Range(1u, sweeps));
  cmd->add_option("--threads", opt->threads, "Worker threads (0 = all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--max-speed", p.max_speed, "Divergence guard: fastest allowed particle (m/s)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--damping", p.linear_damping,
                  "Linear damping k_l of eq. 4: share of velocity removed per 5 ms, in [0, 1)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  auto* pbd = cmd->add_option("--pbd", opt->pbd, "PBD stiffnesses KDIST,KBEND in [0, 1]")
                  ->delimiter(',')
                  ->expected(2)
                  ->check(CLI::Range(0.0, 1.0));
  auto* xpbd = cmd->add_option("--compliance", opt->compliance,
                               "XPBD compliances ADIST (m/N),ABEND (rad/(N m)), each >= 0")
                   ->delimiter(',')
                   ->expected(2)
                   ->check(CLI::NonNegativeNumber);
  pbd->excludes(xpbd);
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  cmd->callback([opt] {
    scene::ClothParams& q = opt->params;
    if (!opt->compliance.empty()) {
      q.response = physics::Response::xpbd;
      q.distance_compliance = opt->compliance[0];
      q.bending_compliance = opt->compliance[1];
    } else if (!opt->pbd.empty()) {
      q.pbd_distance_stiffness = opt->pbd[0];
      q.pbd_bending_stiffness = opt->pbd[1];
    }
  });
  return opt;
}

int run_cloth_command(const ClothOptions& options) {
  scene::ClothScene scene = scene::make_cloth_scene(options.params);
  physics::Executor exec(options.threads);

  std::vector<double> step_ms;
  step_ms.reserve(options.steps);
  physics::StepResult failure;
  std::uint32_t steps_done = 0;
  install_interrupt_handlers();
  const double dt = double(scene.model.solver.dt);
  RunProgress progress("imasim cloth", dt * options.steps, dt, false, std::cerr);
  for (; steps_done < options.steps && interrupt_signal() == 0; ++steps_done) {
    const auto t0 = std::chrono::steady_clock::now();
    const physics::StepResult r = physics::step(scene.model, scene.state, exec);
    const auto t1 = std::chrono::steady_clock::now();
    if (!r.ok()) {
      failure = r;
      break;
    }
    step_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    progress.update(dt * (steps_done + 1));
  }
  progress.finish();
  const double median_ms = median(step_ms);

  const physics::State& s = scene.state;
  bool finite = true;
  for (const Vec3& x : s.particles.position)
    finite = finite && x.allFinite();
  nlohmann::ordered_json out;
  out["particles"] = s.particles.size();
  out["distance_constraints"] = s.constraints.distance.size();
  out["dihedral_constraints"] = s.constraints.dihedral.size();
  out["colours"] = s.constraints.non_empty_groups();
  out["overflow_constraints"] = s.constraints.overflow_size();
  out["threads"] = exec.threads();
  out["steps"] = steps_done;
  out["center_sag_m"] = scene::centre_sag(scene);
  out["max_displacement_m"] = scene::max_displacement(s);
  out["ms_per_step_median"] = median_ms;
  out["state_hash"] = to_hex(physics::position_hash(s));

  add_status(out, finite, failure, steps_done);
  const int signal = interrupt_signal();
  if (signal != 0) out["status"] = "interrupted";
  if (!print_report(out, options.json)) {
    std::cerr << "imasim cloth: cannot write the report to stdout\n";
    return 4;
  }
  if (signal != 0) return interrupted_exit_status(signal);
  return failure.ok() ? 0 : 3;
}

}  // namespace imasim::cli
