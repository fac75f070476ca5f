// Trainee metrics (metrics/trainee_metrics.hpp) on synthetic recordings with known answers.
#include "metrics/trainee_metrics.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace imasim::metrics {
namespace {

// The IMA along z at the origin, the heart 20 mm to -x.
SideReference vessel() {
  geometry::TriangleMesh heart;
  heart.vertices = {Vec3(-0.02, -0.5, -0.5), Vec3(-0.02, 0.5, -0.5), Vec3(-0.02, 0.5, 0.5)};
  heart.triangles = {{0, 1, 2}};
  const std::vector<Vec3> c = {Vec3(0, 0, 0), Vec3(0, 0, 0.1)};
  return make_side_reference(c, heart);
}

// Rows every 1/60 s for `seconds`, both tips still at (x, 0, 0.05) and (0.01 + x, 0, 0.05).
std::vector<TrajectorySample> still(double seconds) {
  std::vector<TrajectorySample> rows;
  for (int k = 0; k <= int(std::lround(seconds * 60)); ++k) {
    TrajectorySample s;
    s.time = k / 60.0;
    s.tools[0].tip = Vec3(0.02, 0, 0.05);
    s.tools[1].tip = Vec3(0.03, 0, 0.05);
    rows.push_back(s);
  }
  return rows;
}

const TraineeMetric& find(const std::vector<TraineeMetric>& m, const std::string& name) {
  for (const TraineeMetric& x : m)
    if (x.name == name) return x;
  static TraineeMetric none;
  ADD_FAILURE() << "no metric " << name;
  return none;
}

TEST(TraineeMetrics, PathLengthIdleTimeAndWorkspace) {
  std::vector<TrajectorySample> rows = still(3);
  // The forceps move 30 mm along z at 30 mm/s during the second second, and 40 mm along x
  // during the third: 70 mm of path, a 30 x 40 mm box (diagonal 50 mm); idle the first second.
  for (TrajectorySample& r : rows) {
    const double z = std::clamp(r.time - 1.0, 0.0, 1.0) * 0.03;
    const double x = std::clamp(r.time - 2.0, 0.0, 1.0) * 0.04;
    r.tools[0].tip = Vec3(0.02 + x, 0, 0.05 + z);
  }
  const std::vector<TraineeMetric> m = trainee_metrics(rows, {}, vessel(), {});
  EXPECT_NEAR(find(m, "path_length_forceps_m").value, 0.07, 1e-12);
  EXPECT_NEAR(find(m, "path_length_hook_m").value, 0, 1e-15);
  EXPECT_NEAR(find(m, "workspace_forceps_m").value, 0.05, 1e-12);
  EXPECT_NEAR(find(m, "idle_time_s").value, 1.0, 1e-9);
  EXPECT_NEAR(find(m, "time_to_complete_s").value, 3.0, 1e-12);
  EXPECT_TRUE(find(m, "path_length_forceps_m").pass);  // well under 2 m
}

TEST(TraineeMetrics, ForcesClutchCollisionsAndEnergy) {
  std::vector<TrajectorySample> rows = still(4);
  for (TrajectorySample& r : rows) {
    // The hook pushes 3 N from 1 s to 2 s (above 2.5 N), 4.5 N twice briefly.
    if (r.time >= 1 && r.time < 2) r.tools[1].force_normal = 3;
    if ((r.time >= 2.5 && r.time < 2.6) || (r.time >= 3.0 && r.time < 3.1))
      r.tools[1].force_normal = Real(4.5);
    // The left clutch pressed twice.
    r.tools[0].clutch = (r.time > 0.5 && r.time < 0.7) || (r.time > 1.5 && r.time < 1.6);
    // The pedal on from 2 s to 3 s, the hook within 2 mm of the IMA's wall for the second half.
    if (r.time >= 2 && r.time < 3) r.pedal = surgery::PedalMode::coag;
    if (r.time >= 2.5 && r.time < 3) r.tools[1].tip = Vec3(0.003, 0, 0.05);
    // The tips meet once (3.5 mm apart).
    if (r.time >= 3.5) r.tools[1].tip = r.tools[0].tip + Vec3(0.0035, 0, 0);
  }
  SessionTotals totals;
  totals.strands_total = 40;
  totals.strands_cut = 38;
  const std::vector<TraineeMetric> m = trainee_metrics(rows, {}, vessel(), totals);
  const double row = 1 / 60.0;
  EXPECT_NEAR(find(m, "time_above_force_s").value, 1.0 + 2 * 0.1, 2 * row);
  EXPECT_EQ(find(m, "excessive_force_events").value, 2);
  EXPECT_EQ(find(m, "clutch_uses").value, 2);
  EXPECT_EQ(find(m, "instrument_collisions").value, 1);
  EXPECT_FALSE(find(m, "instrument_collisions").pass);
  EXPECT_NEAR(find(m, "cautery_on_s").value, 1.0, row);
  EXPECT_NEAR(find(m, "misapplied_energy_s").value, 0.5, row);
  EXPECT_TRUE(find(m, "misapplied_energy_s").pass);  // 0.5 s, within the 1 s allowed
  EXPECT_NEAR(find(m, "strands_divided_share").value, 0.95, 1e-15);
  EXPECT_TRUE(find(m, "strands_divided_share").pass);
}

TEST(TraineeMetrics, EventsCountContactsInjuriesAndGrasps) {
  surgery::EventLog log;
  log.add(0.5, surgery::EventKind::contact_begin, 0, surgery::Tissue::heart);
  log.add(0.6, surgery::EventKind::contact_end, 0, surgery::Tissue::heart);
  log.add(1.0, surgery::EventKind::contact_begin, 1, surgery::Tissue::chest_wall);
  log.add(1.5, surgery::EventKind::contact_begin, 1, surgery::Tissue::fascia);
  log.add(2.0, surgery::EventKind::injury, 1, surgery::Tissue::ima, 3, 12);
  log.add(2.5, surgery::EventKind::grasp, 0, surgery::Tissue::none, 6);
  const std::vector<TraineeMetric> m = trainee_metrics(still(3), log, vessel(), {});
  EXPECT_EQ(find(m, "heart_contacts").value, 1);
  EXPECT_FALSE(find(m, "heart_contacts").pass);  // none allowed
  EXPECT_EQ(find(m, "chest_wall_contacts").value, 1);
  EXPECT_TRUE(find(m, "chest_wall_contacts").pass);
  EXPECT_EQ(find(m, "ima_thermal_injuries").value, 1);
  EXPECT_FALSE(find(m, "ima_thermal_injuries").pass);
  EXPECT_EQ(find(m, "grasps").value, 1);
}

TEST(TraineeMetrics, FasciaOpenedIsTheHooksPathWhileCuttingFascia) {
  std::vector<TrajectorySample> rows = still(2);
  for (TrajectorySample& r : rows) {
    r.tools[1].tip = Vec3(0.005, 0, 0.02 + 0.05 * r.time);  // 50 mm/s along the vessel
    if (r.time < 1) {
      r.pedal = surgery::PedalMode::cut;
      r.tools[1].contact = surgery::Tissue::fascia;
    }
  }
  const std::vector<TraineeMetric> m = trainee_metrics(rows, {}, vessel(), {});
  EXPECT_NEAR(find(m, "fascia_opened_m").value, 0.05, 0.05 / 60 + 1e-12);
  EXPECT_FALSE(find(m, "fascia_opened_m").pass);  // 50 mm of the 80 mm asked for
}

TEST(TraineeMetrics, ThresholdsAreOverriddenByNameAndPassFailFollows) {
  const std::vector<TrajectorySample> rows = still(3);
  const std::vector<TraineeMetric> strict =
      trainee_metrics(rows, {}, vessel(), {}, {}, {{"time_to_complete_s", 2.0}});
  EXPECT_EQ(find(strict, "time_to_complete_s").threshold, 2.0);
  EXPECT_FALSE(find(strict, "time_to_complete_s").pass);  // 3 s > 2 s
  const std::vector<TraineeMetric> lax =
      trainee_metrics(rows, {}, vessel(), {}, {}, {{"time_to_complete_s", 3.0}});
  EXPECT_TRUE(find(lax, "time_to_complete_s").pass);  // at the threshold passes
  EXPECT_THROW(trainee_metrics(rows, {}, vessel(), {}, {}, {{"time_to_finish", 1.0}}),
               MetricsError);
  EXPECT_THROW(trainee_metrics(rows, {}, vessel(), {}, {}, {{"idle_time_s", NAN}}), MetricsError);
}

}  // namespace
}  // namespace imasim::metrics
