#include "trainee_progress.hpp"

namespace imasim::metrics {

namespace {

std::optional<double> time_to_complete(const SessionRecord& s) {
  const TraineeMetric* m = find_metric(s, "time_to_complete_s");
  return m != nullptr ? std::optional<double>(m->value) : std::nullopt;
}

}  // namespace

PassCount pass_count(const SessionRecord& session) {
  PassCount c;
  c.total = session.metrics.size();
  for (const TraineeMetric& m : session.metrics)
    c.passed += m.pass ? 1 : 0;
  return c;
}

const TraineeMetric* find_metric(const SessionRecord& session, std::string_view name) {
  for (const TraineeMetric& m : session.metrics)
    if (m.name == name) return &m;
  return nullptr;
}

const SaiResult* find_sai(const SessionRecord& session, std::string_view instrument) {
  for (const InstrumentSai& i : session.sai)
    if (i.instrument == instrument) return &i.result;
  return nullptr;
}

TraineeProgress trainee_progress(std::span<const SessionRecord> sessions) {
  TraineeProgress p;
  p.sessions = sessions.size();
  if (sessions.empty()) return p;
  p.first = pass_count(sessions.front());
  p.latest = pass_count(sessions.back());
  p.first_time_to_complete_s = time_to_complete(sessions.front());
  p.latest_time_to_complete_s = time_to_complete(sessions.back());
  const double n = double(sessions.size());
  const double mean_x = (n + 1) / 2;  // of 1, 2, ..., n
  double mean_y = 0;
  for (const SessionRecord& s : sessions)
    mean_y += pass_count(s).share() / n;
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < sessions.size(); ++k) {
    const double dx = double(k + 1) - mean_x;
    sxy += dx * (pass_count(sessions[k]).share() - mean_y);
    sxx += dx * dx;
  }
  p.passed_share_trend = sxx > 0 ? sxy / sxx : 0.0;
  return p;
}

}  // namespace imasim::metrics
