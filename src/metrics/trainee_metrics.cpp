#include "metrics/trainee_metrics.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::metrics {

namespace {

using surgery::EventKind;
using surgery::PedalMode;
using surgery::Tissue;

struct Totals {
  double duration = 0;
  std::array<double, 2> path{0, 0}, workspace{0, 0};
  double idle = 0, above_force = 0, cautery_on = 0, misapplied = 0, fascia_opened = 0;
  int clutch_uses = 0, excessive_force = 0, collisions = 0;
};

Totals accumulate(std::span<const TrajectorySample> rows, const SideReference& ima,
                  const SessionTotals& session, const MetricLimits& limits) {
  Totals t;
  if (rows.empty()) return t;
  std::array<Vec3, 2> lo{rows[0].tools[0].tip, rows[0].tools[1].tip}, hi = lo;
  bool above = false, close = false;
  std::array<bool, 2> clutched{rows[0].tools[0].clutch, rows[0].tools[1].clutch};
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const TrajectorySample& a = rows[k - 1];
    const TrajectorySample& b = rows[k];
    const double dt = std::max(0.0, b.time - a.time);
    bool moving = false;
    for (std::size_t h = 0; h < 2; ++h) {
      const Real step = (b.tools[h].tip - a.tools[h].tip).norm();
      t.path[h] += double(step);
      moving = moving || (dt > 0 && double(step) / dt >= double(limits.idle_speed));
      lo[h] = lo[h].cwiseMin(b.tools[h].tip);
      hi[h] = hi[h].cwiseMax(b.tools[h].tip);
      if (b.tools[h].clutch && !clutched[h]) ++t.clutch_uses;
      clutched[h] = b.tools[h].clutch;
    }
    if (!moving) t.idle += dt;
    // The state of the earlier row holds over the interval.
    const Real force = std::max(a.tools[0].force_normal, a.tools[1].force_normal);
    if (force > limits.force_threshold) t.above_force += dt;
    const Real next_force = std::max(b.tools[0].force_normal, b.tools[1].force_normal);
    if (next_force > limits.excessive_force && !above) ++t.excessive_force;
    above = next_force > limits.excessive_force;
    const bool near = (b.tools[0].tip - b.tools[1].tip).norm() < limits.collision_distance;
    if (near && !close) ++t.collisions;
    close = near;
    if (a.pedal != PedalMode::off) {
      t.cautery_on += dt;
      if (side_distance(ima, a.tools[1].tip).distance < session.ima_radius + limits.energy_margin)
        t.misapplied += dt;
    }
    if (a.pedal == PedalMode::cut && a.tools[1].contact == Tissue::fascia)
      t.fascia_opened += double((b.tools[1].tip - a.tools[1].tip).norm());
  }
  t.duration = rows.back().time - rows.front().time;
  for (std::size_t h = 0; h < 2; ++h)
    t.workspace[h] = double((hi[h] - lo[h]).norm());
  return t;
}

int count_events(const surgery::EventLog& log, EventKind kind, Tissue tissue) {
  int n = 0;
  for (const surgery::Event& e : log.events)
    n += e.kind == kind && (tissue == Tissue::none || e.tissue == tissue) ? 1 : 0;
  return n;
}

}  // namespace

std::vector<std::string> trainee_metric_names() {
  std::vector<std::string> names;
  for (const TraineeMetric& m : trainee_metrics({}, {}, SideReference{}, {}))
    names.push_back(m.name);
  return names;
}

std::vector<TraineeMetric> trainee_metrics(std::span<const TrajectorySample> rows,
                                           const surgery::EventLog& events,
                                           const SideReference& ima, const SessionTotals& session,
                                           const MetricLimits& limits,
                                           const std::map<std::string, double>& overrides) {
  const Totals t = accumulate(rows, ima, session, limits);
  const double strands =
      session.strands_total > 0 ? double(session.strands_cut) / double(session.strands_total) : 0;
  // name, unit, value, threshold, higher is better, meaning
  std::vector<TraineeMetric> m = {
      {"time_to_complete_s", "s", "simulated time from the first row to the last", t.duration, 600,
       false},
      {"path_length_forceps_m", "m", "distance the forceps' tip travelled (economy of motion)",
       t.path[0], 2.0, false},
      {"path_length_hook_m", "m", "distance the hook's tip travelled (economy of motion)",
       t.path[1], 2.0, false},
      {"idle_time_s", "s", "time both tips moved slower than 1 mm/s", t.idle, 60, false},
      {"workspace_forceps_m", "m", "diagonal of the box the forceps' tip stayed in", t.workspace[0],
       0.15, false},
      {"workspace_hook_m", "m", "diagonal of the box the hook's tip stayed in", t.workspace[1],
       0.15, false},
      {"clutch_uses", "1", "times a clutch was pressed (either hand)", double(t.clutch_uses), 40,
       false},
      {"heart_contacts", "1", "times an instrument touched the heart",
       double(count_events(events, EventKind::contact_begin, Tissue::heart)), 0, false},
      {"chest_wall_contacts", "1", "times an instrument touched the chest wall",
       double(count_events(events, EventKind::contact_begin, Tissue::chest_wall)), 10, false},
      {"instrument_collisions", "1", "times the two tips came within 5 mm of each other",
       double(t.collisions), 0, false},
      {"time_above_force_s", "s", "time either hand's normal force exceeded 2.5 N", t.above_force,
       5, false},
      {"excessive_force_events", "1", "times either hand's normal force rose above 4 N",
       double(t.excessive_force), 2, false},
      {"cautery_on_s", "s", "time the pedal was pressed", t.cautery_on, 300, false},
      {"misapplied_energy_s", "s",
       "time the pedal was pressed with the hook's tip within 2 mm of the IMA's wall", t.misapplied,
       1, false},
      {"ima_thermal_injuries", "1", "times heat injured the IMA",
       double(count_events(events, EventKind::injury, Tissue::none)), 0, false},
      {"strands_divided_share", "1", "share of the fat strands divided", strands, 0.9, true},
      {"fascia_opened_m", "m", "the hook's path while cutting in contact with the fascia",
       t.fascia_opened, 0.08, true},
      {"grasps", "1", "times the forceps closed on tissue",
       double(count_events(events, EventKind::grasp, Tissue::none)), 0, true},
  };
  for (const auto& entry : overrides) {
    // (No structured binding: clang 14 cannot capture one in a lambda.)
    const std::string& name = entry.first;
    auto it = std::find_if(m.begin(), m.end(),
                           [&name](const TraineeMetric& x) { return x.name == name; });
    if (it == m.end()) throw MetricsError("no metric is called '" + name + "'");
    if (!std::isfinite(entry.second))
      throw MetricsError("the threshold of '" + name + "' is not finite");
    it->threshold = entry.second;
  }
  for (TraineeMetric& x : m)
    x.pass = x.higher_is_better ? x.value >= x.threshold : x.value <= x.threshold;
  return m;
}

}  // namespace imasim::metrics
