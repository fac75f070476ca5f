#include "run_trainee_record.hpp"

#include <cstdlib>
#include <filesystem>

#include "math/printable.hpp"
#include "metrics/records_path.hpp"
#include "metrics/trainee_name.hpp"

namespace imasim::cli {

namespace {

constexpr std::size_t kEchoBytes = 80;  // of a refused name, in a message

std::string chosen_trainee(const std::string& option) {
  if (!option.empty()) {
    if (const std::string problem = metrics::trainee_name_problem(option); !problem.empty())
      throw metrics::RecordsError("--trainee '" + printable(option, kEchoBytes) + "' " + problem);
    return option;
  }
  const char* user = std::getenv("USER");
  if (user == nullptr || *user == '\0') return "anonymous";
  if (const std::string problem = metrics::trainee_name_problem(user); !problem.empty())
    throw metrics::RecordsError("the user name $USER ('" + printable(user, kEchoBytes) + "') " +
                                problem + "; name the trainee with --trainee NAME");
  return user;
}

}  // namespace

RecordsChoice choose_records(const std::string& trainee_option, const std::string& db_option) {
  RecordsChoice c;
  c.trainee = chosen_trainee(trainee_option);
  if (!db_option.empty()) {
    c.database = db_option;
  } else {
    c.database = metrics::default_records_path();
    metrics::create_records_directory(c.database);
  }
  return c;
}

metrics::OperatorKind operator_kind_of(const std::string& devices, bool replay) {
  if (replay) return metrics::OperatorKind::replay;
  // The emulator's devices play an input script: no person moves them.
  if (devices == "script" || devices == "emulator") return metrics::OperatorKind::script;
  if (devices == "autopilot") return metrics::OperatorKind::scripted_operator;
  return metrics::OperatorKind::human_device;
}

nlohmann::ordered_json append_trainee_record(metrics::TraineeRecords& records,
                                             RunRecording& recording,
                                             metrics::SessionRecord session) {
  const metrics::SessionRecord scored = recording.scored_session();
  session.sai_radius = scored.sai_radius;
  session.sai = scored.sai;
  session.metrics = scored.metrics;
  const metrics::AppendResult appended = records.append_or_hold(session);
  nlohmann::ordered_json note;
  note["database"] = std::filesystem::absolute(records.path()).string();
  if (appended.pending.empty()) {
    note["session_id"] = appended.id;
  } else {  // the records were locked: the session waits beside them for the next recorded run
    note["session_id"] = nullptr;
    note["pending"] = std::filesystem::absolute(appended.pending).string();
  }
  note["trainee"] = session.trainee;
  recording.add_to_side("trainee_record", note);
  return note;
}

}  // namespace imasim::cli
