#include "run_autopilot.hpp"

#include "autopilot/harvest_outcome.hpp"
#include "cli_checks.hpp"
#include "console/console_mapping.hpp"

namespace imasim::cli {

void add_autopilot_options(CLI::App& run, AutopilotOptions& o) {
  run.add_flag("--autopilot", o.enabled,
               "The scripted operator performs the standard task (harvest 10 cm of the left "
               "IMA) through the device interface: a test operator, not a model of surgeons");
  run.add_option("--operator-seed", o.params.seed, "The operator's seed (tremor)")
      ->capture_default_str();
  run.add_option("--operator-speed", o.params.speed,
                 "The operator's speed on its nominal speeds (1: cutting at 10 mm/s)")
      ->capture_default_str()
      ->check(finite_range(0.1, 10.0));
  run.add_option("--side-bias", o.params.side_bias,
                 "Shift of the operator's working lines across the vessel, > 0 away from the "
                 "heart (m)")
      ->capture_default_str()
      ->check(finite_range(-0.005, 0.005));
  run.add_option("--tremor", o.params.tremor, "RMS of the operator's 8-12 Hz tremor (m)")
      ->capture_default_str()
      ->check(finite_range(0.0, 0.002));
  run.add_option("--keep-out", o.params.keep_out_base,
                 "Distance the operator keeps from the heart's surface (m)")
      ->capture_default_str()
      ->check(finite_range(0.0, 0.02));
  run.add_option("--keep-out-gain", o.params.keep_out_gain,
                 "Extra keep-out per metre of the heart's excursion under the segment")
      ->capture_default_str()
      ->check(finite_range(0.0, 10.0));
}

RunAutopilot::RunAutopilot(const session::SurgicalSession& session,
                           const autopilot::OperatorParams& params)
    : params_(params), operator_(autopilot::plan_harvest(session, params), params) {}

session::SessionInput RunAutopilot::next(const session::SurgicalSession& session) {
  // What the endoscope shows the operator: where its instruments are.
  operator_.observe(devices::Hand::left, session.stations[0].pose);
  operator_.observe(devices::Hand::right, session.stations[1].pose);
  operator_.poll(session.scene.patch.world.state.time, console_);
  return console::to_session_input(console_, session);
}

nlohmann::ordered_json RunAutopilot::report(const session::SurgicalSession& session) const {
  const autopilot::HarvestPlan& plan = operator_.plan();
  const autopilot::HarvestOutcome out = autopilot::harvest_outcome(session, plan);
  const double now = session.scene.patch.world.state.time;
  nlohmann::ordered_json j;
  j["kind"] = "scripted operator (a test operator, not a model of surgeons)";
  j["seed"] = params_.seed;
  j["speed"] = params_.speed;
  j["side_bias_m"] = params_.side_bias;
  j["tremor_m"] = params_.tremor;
  j["heart_excursion_m"] = plan.heart_excursion;
  j["keep_out_m"] = plan.keep_out;
  j["plan_s"] = plan.end_time;
  nlohmann::ordered_json phases = nlohmann::ordered_json::array();
  for (const autopilot::PhaseMark& m : plan.phases)
    phases.push_back({{"name", m.name}, {"start_s", m.time}});
  j["phases"] = phases;
  j["phase_reached"] = operator_.phase_at(now);
  j["plan_completed"] = operator_.finished(now);
  j["pedicle_strands"] = out.pedicle_strands;
  j["pedicle_strands_divided"] = out.pedicle_strands_divided;
  j["pedicle_divided_share"] = out.divided_share();
  j["fascia_edges_cut"] = out.fascia_edges_cut;
  j["ima_injuries"] = out.ima_injuries;
  j["task_finished"] = operator_.finished(now) && autopilot::harvest_finished(out);
  return j;
}

}  // namespace imasim::cli
