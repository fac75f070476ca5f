#pragma once
// `imasim run --autopilot`: the scripted operator drives both instruments and the
// pedal through the device interface (autopilot/scripted_operator.hpp), as a surgeon's console
// would; the run reports its plan and how far the harvest got.
#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>

#include "autopilot/operator_params.hpp"
#include "autopilot/scripted_operator.hpp"
#include "runner/input_source.hpp"
#include "session/surgical_session.hpp"

namespace imasim::cli {

struct AutopilotOptions {
  bool enabled = false;
  autopilot::OperatorParams params;
};

// Registers --autopilot and the operator's parameters on `run`.
void add_autopilot_options(CLI::App& run, AutopilotOptions& options);

// A runner input source (runner/input_source.hpp).
class RunAutopilot final : public runner::InputSource {
 public:
  // Plans the harvest on the session as set up; throws std::invalid_argument for a scene it
  // cannot plan in.
  RunAutopilot(const session::SurgicalSession& session, const autopilot::OperatorParams& params);

  // The step's input from the operator at the session's time.
  session::SessionInput next(const session::SurgicalSession& session) override;
  double end_time() const { return operator_.plan().end_time; }
  // The report's "operator" object: its parameters, plan, phase reached and the outcome.
  nlohmann::ordered_json report(const session::SurgicalSession& session) const;

 private:
  autopilot::OperatorParams params_;
  autopilot::ScriptedOperator operator_;
  devices::ConsoleInput console_;
};

}  // namespace imasim::cli
