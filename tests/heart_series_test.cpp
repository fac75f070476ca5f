// A heart phase series from files: the procedural heart written out in millimetres, one OBJ
// per phase, loads back as the same model; broken series are refused naming the file; a scene
// runs on a loaded heart, from a scene file with relative paths.
#include "scene/heart_series.hpp"

#include <gtest/gtest.h>

#include "mesh_writers.hpp"
#include "physics/executor.hpp"
#include "scene/scene_file.hpp"
#include "scene/thorax_scene.hpp"

namespace imasim::scene {
namespace {

tissue::HeartModel procedural() {
  return tissue::make_procedural_heart(default_thorax_scene_params().heart);
}

// Writes the model's phases as OBJ files in mm; returns their paths.
std::vector<std::string> write_phases(const test::TestFolder& dir, const tissue::HeartModel& h,
                                      const std::string& stem = "phase") {
  std::vector<std::string> paths;
  for (std::size_t k = 0; k < h.keyframes.size(); ++k) {
    geometry::TriangleMesh m = h.topology;
    for (std::size_t v = 0; v < m.vertices.size(); ++v)
      m.vertices[v] = h.keyframes[k][v] * 1000;
    const std::string name = stem + std::to_string(k) + ".obj";
    test::write_obj(dir / name, m);
    paths.push_back((dir / name).string());
  }
  return paths;
}

TEST(HeartSeries, ProceduralHeartWrittenInMillimetresLoadsBack) {
  const test::TestFolder dir;
  const tissue::HeartModel h = procedural();
  const tissue::HeartModel loaded = load_heart_series({write_phases(dir, h), {}});
  ASSERT_EQ(loaded.keyframes.size(), h.keyframes.size());
  ASSERT_EQ(loaded.component_start, h.component_start);
  ASSERT_EQ(loaded.component_triangle_start, h.component_triangle_start);
  // Welding numbers vertices in order of first use: map each loaded vertex to the original
  // nearest it in the first phase (vertices are millimetres apart, far above float rounding).
  std::vector<std::uint32_t> original(loaded.topology.vertices.size());
  for (std::size_t v = 0; v < original.size(); ++v) {
    Real best = 1e9;
    for (std::size_t u = 0; u < h.topology.vertices.size(); ++u) {
      const Real d = (loaded.keyframes[0][v] - h.keyframes[0][u]).norm();
      if (d < best) best = d, original[v] = static_cast<std::uint32_t>(u);
    }
  }
  for (std::size_t t = 0; t < h.topology.triangles.size(); ++t) {
    const geometry::Triangle& tri = loaded.topology.triangles[t];
    EXPECT_EQ((geometry::Triangle{original[tri[0]], original[tri[1]], original[tri[2]]}),
              h.topology.triangles[t]);
  }
  // Files hold floats: a coordinate of at most 150 mm is within 2^-24 * 150 mm of the double.
  for (std::size_t k = 0; k < h.keyframes.size(); ++k) {
    for (std::size_t v = 0; v < original.size(); ++v)
      ASSERT_NEAR((loaded.keyframes[k][v] - h.keyframes[k][original[v]]).norm(), 0, 2e-8);
    for (std::uint32_t c = 0; c < 2; ++c) {
      EXPECT_NEAR(tissue::component_volume(loaded, loaded.keyframes[k], c),
                  tissue::component_volume(h, h.keyframes[k], c), 1e-9);
    }
  }
}

TEST(HeartSeries, ComponentsBecomeContiguousRanges) {
  // Interleave the two ventricles' triangles in the file: loading regroups them.
  const test::TestFolder dir;
  tissue::HeartModel h = procedural();
  const std::size_t half = h.component_triangle_start[1];
  std::vector<geometry::Triangle> mixed;
  for (std::size_t t = 0; t < half; ++t) {
    mixed.push_back(h.topology.triangles[half + t]);
    mixed.push_back(h.topology.triangles[t]);
  }
  h.topology.triangles = mixed;
  const tissue::HeartModel loaded = load_heart_series({write_phases(dir, h), {}});
  ASSERT_EQ(loaded.component_start.size(), 3u);
  for (std::uint32_t c = 0; c < 2; ++c) {
    for (std::uint32_t t = loaded.component_triangle_start[c];
         t < loaded.component_triangle_start[c + 1]; ++t) {
      for (std::uint32_t v : loaded.topology.triangles[t]) {
        ASSERT_GE(v, loaded.component_start[c]);
        ASSERT_LT(v, loaded.component_start[c + 1]);
      }
    }
    EXPECT_GT(tissue::component_volume(loaded, loaded.keyframes[0], c), 0);
  }
}

void expect_error(const HeartSeriesSpec& spec, const std::string& expected) {
  try {
    load_heart_series(spec);
    ADD_FAILURE() << "loaded; expected: " << expected;
  } catch (const MeshFileError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(HeartSeries, BrokenSeriesNameTheFile) {
  const test::TestFolder dir;
  const tissue::HeartModel h = procedural();
  std::vector<std::string> paths = write_phases(dir, h);
  // A phase with another topology.
  tissue::HeartModel other = h;
  std::swap(other.topology.triangles[5], other.topology.triangles[6]);
  const std::vector<std::string> other_paths = write_phases(dir, other, "other");
  std::vector<std::string> mixed = paths;
  mixed[3] = other_paths[3];
  expect_error({mixed, {}}, other_paths[3] + ": triangle 5 differs from the first phase's");
  // A phase with fewer vertices.
  geometry::TriangleMesh tetra;
  tetra.vertices = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, 0), Vec3(0, 0, 10)};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  test::write_obj(dir / "tetra.obj", tetra);
  mixed = paths;
  mixed[1] = (dir / "tetra.obj").string();
  expect_error({mixed, {}}, mixed[1] + ": phase 1 has 4 vertices");
  // Inward-facing surfaces.
  tissue::HeartModel inward = h;
  for (geometry::Triangle& t : inward.topology.triangles)
    std::swap(t[1], t[2]);
  expect_error({write_phases(dir, inward, "inward"), {}}, "its triangles face inwards");
  // An open surface is capped (tests/patient_heart_test.cpp), but not one with two holes that
  // touch at a vertex: remove two triangles that share exactly one vertex.
  tissue::HeartModel pinched = h;
  std::vector<geometry::Triangle>& tris = pinched.topology.triangles;
  const geometry::Triangle first = tris[0];
  for (std::size_t t = 1; t < tris.size(); ++t) {
    int shared = 0;
    for (std::uint32_t a : tris[t])
      shared += std::count(first.begin(), first.end(), a) > 0 ? 1 : 0;
    if (shared == 1) {
      tris.erase(tris.begin() + std::ptrdiff_t(t));
      break;
    }
  }
  tris.erase(tris.begin());
  expect_error({write_phases(dir, pinched, "pinched"), {}},
               "is on two boundary loops (they touch there): the holes cannot be capped");
  expect_error({{paths[0]}, {}}, "at least two phase files");
}

TEST(HeartSeries, SceneFileWithRelativePhaseFilesRunsOnTheLoadedHeart) {
  const test::TestFolder dir;
  // The scene's procedural heart is placed by the typical anatomy: write that heart out.
  ThoraxSceneParams typical = default_thorax_scene_params();
  const ThoraxScene reference = make_thorax_scene(typical);
  tissue::HeartParams placed = typical.heart;
  placed.centre = reference.layout.heart_centre;
  placed.long_axis = reference.layout.heart_long_axis;
  placed.lateral = reference.layout.heart_lateral;
  const std::vector<std::string> placed_paths =
      write_phases(dir, tissue::make_procedural_heart(placed), "placed");
  std::string list;
  for (std::size_t k = 0; k < placed_paths.size(); ++k)
    list += (k ? ", \"" : "\"") + std::string("placed") + std::to_string(k) + ".obj\"";
  test::write_text(dir / "scene.toml", "[heart]\nphase_files = [" + list + "]\n");
  const ThoraxSceneParams params = load_scene_file((dir / "scene.toml").string());
  ASSERT_EQ(params.heart_series.phase_files.size(), placed_paths.size());
  EXPECT_EQ(params.heart_series.phase_files[2], placed_paths[2]);  // resolved against the file

  ThoraxScene s = make_thorax_scene(params);
  ThoraxScene procedural_scene = make_thorax_scene(typical);
  physics::Executor exec(1);
  for (int n = 0; n < 100; ++n) {
    ASSERT_TRUE(step_thorax_scene(s, exec).ok());
    ASSERT_TRUE(step_thorax_scene(procedural_scene, exec).ok());
  }
  // The loaded heart is the procedural one to float precision: the two scenes agree closely.
  const auto& a = s.patch.world.state.particles.position;
  const auto& b = procedural_scene.patch.world.state.particles.position;
  Real worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, (a[i] - b[i]).norm());
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(s.heart.last_contacts + procedural_scene.heart.last_contacts, 0u);
}

}  // namespace
}  // namespace imasim::scene
