// A patient's heart as segmentations give it: a left ventricle as a structured grid in
// millimetres and scanner coordinates, its apex pole one position repeated along a whole row, open
// at the valve plane, two phases. It loads (welded, collapsed triangles dropped, the base
// capped), is placed under the IMA by heart.placement = "auto", and beats there like the built-in
// heart; left where its file puts it, inside the tissue, it is refused with the overlap named.
#include <gtest/gtest.h>

#include "mesh_writers.hpp"
#include "physics/executor.hpp"
#include "scene/heart_placement.hpp"
#include "scene/scene_file.hpp"
#include "scene/thorax_scene.hpp"

namespace imasim::scene {
namespace {

constexpr std::uint32_t kRows = 14, kSegments = 56;

// Half a prolate ellipsoid, apex at -z: row 0 is the apex pole (kSegments copies of one point),
// row kRows the open base ring at z = 0. Radius and depth in mm; then turned and moved as a
// scanner's coordinates would put it.
geometry::TriangleMesh lv_grid(Real radius, Real depth) {
  geometry::TriangleMesh m;
  const Real pi = Real(3.14159265358979323846);
  for (std::uint32_t j = 0; j <= kRows; ++j) {
    const Real phi = pi / 2 * Real(j) / Real(kRows);
    for (std::uint32_t i = 0; i < kSegments; ++i) {
      const Real theta = 2 * pi * Real(i) / Real(kSegments);
      const Vec3 local(radius * std::sin(phi) * std::cos(theta),
                       radius * std::sin(phi) * std::sin(theta), -depth * std::cos(phi));
      m.vertices.push_back(axis_angle(Vec3(1, 1, 0).normalized(), Real(0.7)) * local +
                           Vec3(120, -80, 310));
    }
  }
  for (std::uint32_t j = 0; j < kRows; ++j) {
    for (std::uint32_t i = 0; i < kSegments; ++i) {
      const std::uint32_t a = j * kSegments + i, b = j * kSegments + (i + 1) % kSegments;
      const std::uint32_t c = a + kSegments, d = b + kSegments;
      m.triangles.push_back({a, b, d});  // outward
      m.triangles.push_back({a, d, c});
    }
  }
  return m;
}

// End-diastole and end-systole (ejection fraction about a half), as OBJ files; a scene file
// naming them with `extra` keys in its [heart] table.
std::string write_patient_scene(const test::TestFolder& dir, const std::string& extra) {
  test::write_obj(dir / "lv_ed.obj", lv_grid(26, 80));
  test::write_obj(dir / "lv_es.obj", lv_grid(20, 72));
  test::write_text(
      dir / "scene.toml",
      "[heart]\nphase_files = [\"lv_ed.obj\", \"lv_es.obj\"]\nmesh_scale = 0.001\n" + extra);
  return (dir / "scene.toml").string();
}

bool has_note(const ThoraxScene& s, const std::string& text) {
  for (const std::string& n : s.setup_notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

TEST(PatientHeart, AnOpenLvWithARepeatedApexLoadsAndIsPlacedUnderTheIma) {
  const test::TestFolder dir;
  const std::string scene_file = write_patient_scene(dir, "placement = \"auto\"\n");
  ThoraxScene s = make_thorax_scene(load_scene_file(scene_file));
  // Each repair said so: the 56 collapsed apex triangles, the capped base, the placement.
  EXPECT_TRUE(has_note(s, "56 triangles per phase collapsed")) << s.setup_notes.front();
  EXPECT_TRUE(has_note(s, "1 boundary loops were closed with a cap of 56 triangles"));
  EXPECT_TRUE(has_note(s, "heart.placement = \"auto\""));
  // The apex found from the shape points where the scene's heart axis does.
  tissue::HeartModel placed;
  placed.keyframes = {s.heart.current};
  placed.component_start = {0, std::uint32_t(s.heart.current.size())};
  EXPECT_GT(measure_heart_shape(placed).long_axis.dot(s.layout.heart_long_axis.normalized()), 0.99);

  // Two seconds of beating: the IMA moves as with the built-in heart (a few millimetres).
  physics::Executor exec(1);
  const tissue::TissueWorld& w = s.patch.world;
  const tissue::MeshObject& ima = w.meshes[s.patch.ima];
  Real ima_motion = 0;
  std::uint32_t contacts = 0;
  for (int n = 0; n < 400; ++n) {
    ASSERT_TRUE(step_thorax_scene(s, exec).ok()) << "step " << n;
    contacts = std::max(contacts, s.heart.last_contacts);
    for (std::uint32_t k = 0; k < ima.particle_count; ++k) {
      const std::uint32_t i = ima.first_particle + k;
      ima_motion = std::max(
          ima_motion,
          Real((w.state.particles.position[i] - w.state.particles.rest_position[i]).norm()));
    }
  }
  // It sits under the IMA as the built-in heart does: the gap between the IMA and the heart's
  // surface within 3 mm of the built-in's (the shapes differ: only their tops are matched).
  const auto ima_clearance = [](ThoraxScene& scene) {
    const tissue::TissueWorld& world = scene.patch.world;
    const tissue::MeshObject& vessel = world.meshes[scene.patch.ima];
    Real clearance = std::numeric_limits<Real>::infinity();
    for (std::uint32_t k = 0; k < vessel.particle_count; ++k) {
      clearance = std::min(
          clearance,
          tissue::heart_signed_distance(
              scene.heart, world.state.particles.position[vessel.first_particle + k], Real(0.1)));
    }
    return clearance;
  };
  ThoraxScene builtin = make_thorax_scene(default_thorax_scene_params());
  EXPECT_NEAR(ima_clearance(s), ima_clearance(builtin), 0.003);
  EXPECT_LT(ima_motion, 0.006);
  EXPECT_EQ(s.missed_heart_contacts, 0u);
}

TEST(PatientHeart, AHeartLeftInsideTheTissueIsRefusedWithTheOverlapNamed) {
  const test::TestFolder dir;
  // Its base centre (file origin before the move) brought to the IMA's mid-course.
  const ThoraxScene typical = make_thorax_scene(default_thorax_scene_params());
  const Vec3 t = typical.layout.ima_midpoint - Vec3(0.120, -0.080, 0.310);
  const std::string scene_file =
      write_patient_scene(dir, "mesh_translation_m = [" + std::to_string(t.x()) + ", " +
                                   std::to_string(t.y()) + ", " + std::to_string(t.z()) + "]\n");
  try {
    make_thorax_scene(load_scene_file(scene_file));
    FAIL() << "a heart inside the tissue was accepted";
  } catch (const HeartPlacementError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("the heart starts inside the tissue: "), std::string::npos) << m;
    EXPECT_NE(m.find("vertices of the fascia, the IMA and the chest wall lie inside it, up to "),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("move the phase meshes with heart.mesh_translation_m, or set "
                     "heart.placement = \"auto\""),
              std::string::npos)
        << m;
  }
}

TEST(PatientHeart, PlacementIsAWordFromItsList) {
  const test::TestFolder dir;
  const std::string scene_file = write_patient_scene(dir, "placement = \"automatic\"\n");
  try {
    load_scene_file(scene_file);
    FAIL();
  } catch (const SceneFileError& e) {
    EXPECT_NE(std::string(e.what()).find(":4:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("heart.placement"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected \"file\" or \"auto\", got \"automatic\""),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace imasim::scene
