// Mesh loading: each format loads a small mesh written here; scale and transforms apply; broken
// files give messages that name the file and the defect.
#include "scene/mesh_file.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "mesh_writers.hpp"

namespace imasim::scene {
namespace {

// A closed, outward-oriented tetrahedron with 10 mm edges along the axes (file units: mm).
geometry::TriangleMesh tetrahedron_mm() {
  geometry::TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, 0), Vec3(0, 0, 10)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

MeshLoadOptions closed_surface() {
  MeshLoadOptions o;
  o.checks.require_closed = true;
  return o;
}

// The loaded mesh is the tetrahedron in metres: 4 welded vertices, outward, volume (0.01)^3/6.
void expect_tetrahedron_in_metres(const geometry::TriangleMesh& mesh, const Vec3& offset) {
  ASSERT_EQ(mesh.vertex_count(), 4u);
  ASSERT_EQ(mesh.triangle_count(), 4u);
  Vec3 lo = mesh.vertices[0], hi = lo;
  for (const Vec3& v : mesh.vertices)
    lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  // Coordinates pass through float in the file formats: 10 mm is exact, 0.001 is not.
  EXPECT_NEAR((lo - offset).norm(), 0, 1e-12);
  EXPECT_NEAR((hi - offset - Vec3(0.01, 0.01, 0.01)).norm(), 0, 1e-12);
  EXPECT_NEAR(geometry::enclosed_volume(mesh.vertices, mesh.triangles), 1e-6 / 6, 1e-18);
}

TEST(MeshFile, ObjLoads) {
  const test::TestFolder dir;
  test::write_obj(dir / "t.obj", tetrahedron_mm());
  expect_tetrahedron_in_metres(load_mesh_file(dir / "t.obj", closed_surface()), Vec3::Zero());
}

TEST(MeshFile, AsciiStlLoadsAndWeldsItsVertices) {
  const test::TestFolder dir;
  test::write_stl_ascii(dir / "t.stl", tetrahedron_mm());
  expect_tetrahedron_in_metres(load_mesh_file(dir / "t.stl", closed_surface()), Vec3::Zero());
}

TEST(MeshFile, BinaryStlLoads) {
  const test::TestFolder dir;
  test::write_stl_binary(dir / "t.stl", tetrahedron_mm());
  expect_tetrahedron_in_metres(load_mesh_file(dir / "t.stl", closed_surface()), Vec3::Zero());
}

TEST(MeshFile, PlyLoads) {
  const test::TestFolder dir;
  test::write_ply_ascii(dir / "t.ply", tetrahedron_mm());
  expect_tetrahedron_in_metres(load_mesh_file(dir / "t.ply", closed_surface()), Vec3::Zero());
}

TEST(MeshFile, GltfLoadsWithItsNodeTransform) {
  const test::TestFolder dir;
  test::write_gltf(dir / "t.gltf", tetrahedron_mm(), Vec3(5, 0, 0));
  expect_tetrahedron_in_metres(load_mesh_file(dir / "t.gltf", closed_surface()), Vec3(0.005, 0, 0));
}

TEST(MeshFile, TransformScalesRotatesThenTranslates) {
  const test::TestFolder dir;
  test::write_obj(dir / "t.obj", tetrahedron_mm());
  MeshLoadOptions o;
  o.transform.scale = 0.01;                     // cm -> m
  o.transform.rotation = Vec3(0, 0, M_PI / 2);  // 90 degrees about z
  o.transform.translation = Vec3(1, 2, 3);
  const geometry::TriangleMesh m = load_mesh_file(dir / "t.obj", o);
  // Welding numbers vertices in order of first use: find each expected one by position.
  // (10, 0, 0) cm becomes (0, 0.1, 0) m after the turn, then moves by t; (0, 10, 0) cm becomes
  // (-0.1, 0, 0) m.
  auto nearest = [&](const Vec3& x) {
    Real best = 1e9;
    for (const Vec3& v : m.vertices)
      best = std::min(best, (v - x).norm());
    return best;
  };
  EXPECT_LT(nearest(Vec3(1, 2, 3)), 1e-15);
  EXPECT_LT(nearest(Vec3(1, 2.1, 3)), 1e-15);
  EXPECT_LT(nearest(Vec3(0.9, 2, 3)), 1e-15);
  EXPECT_LT(nearest(Vec3(1, 2, 3.1)), 1e-15);
}

void expect_error(const std::filesystem::path& path, const MeshLoadOptions& o,
                  const std::string& expected) {
  try {
    load_mesh_file(path, o);
    ADD_FAILURE() << path << " loaded; expected: " << expected;
  } catch (const MeshFileError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
    EXPECT_NE(what.find(expected), std::string::npos) << what;
  }
}

TEST(MeshFile, MissingFileIsNamed) {
  const test::TestFolder dir;
  expect_error(dir / "absent.obj", {}, "no such file");
  expect_error(dir.path(), {}, "not a regular file");
}

TEST(MeshFile, CorruptFilesAreRefused) {
  const test::TestFolder dir;
  // A binary STL that announces 1000 triangles and holds one.
  geometry::TriangleMesh one = tetrahedron_mm();
  one.triangles.resize(1);
  test::write_stl_binary(dir / "short.stl", one);
  std::string bytes;
  {
    std::ifstream in(dir / "short.stl", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  bytes[80] = char(0xe8), bytes[81] = char(0x03);  // count = 1000
  test::write_text(dir / "short.stl", bytes);
  expect_error(dir / "short.stl", {}, "cannot read the mesh");
  test::write_text(dir / "noise.ply", std::string("\x01\x02\x03 not a mesh at all", 22));
  expect_error(dir / "noise.ply", {}, "PLY header line 1: expected 'ply' (not a PLY file)");
  test::write_text(dir / "bad.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [");
  expect_error(dir / "bad.gltf", {}, "cannot read the mesh");
}

TEST(MeshFile, EmptyMeshIsRefused) {
  const test::TestFolder dir;
  test::write_text(dir / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  try {
    load_mesh_file(dir / "points.obj");
    ADD_FAILURE() << "a file without faces loaded";
  } catch (const MeshFileError& e) {
    const std::string what = e.what();
    EXPECT_TRUE(what.find("no triangles") != std::string::npos ||
                what.find("cannot read the mesh") != std::string::npos)
        << what;
  }
}

TEST(MeshFile, NonManifoldMeshIsRefused) {
  const test::TestFolder dir;
  geometry::TriangleMesh fin = tetrahedron_mm();
  fin.vertices.push_back(Vec3(-10, -10, 0));
  fin.triangles.push_back({0, 1, 4});  // a third triangle on the tetrahedron's edge (0, 1)
  test::write_obj(dir / "fin.obj", fin);
  // Welded, file vertices 0, 2, 1, 3, 4 are numbered 0..4 (order of first use).
  expect_error(dir / "fin.obj", {}, "edge (0, 2) is shared by more than two triangles");
}

TEST(MeshFile, DegenerateTriangleIsRefused) {
  const test::TestFolder dir;
  geometry::TriangleMesh flat;
  flat.vertices = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(20, 0, 0)};
  flat.triangles = {{0, 1, 2}};
  test::write_obj(dir / "flat.obj", flat);
  expect_error(dir / "flat.obj", {}, "triangle 0 (vertices 0, 1, 2) is degenerate");
}

TEST(MeshFile, OpenSurfaceIsRefusedWhereAClosedOneIsNeeded) {
  const test::TestFolder dir;
  geometry::TriangleMesh open = tetrahedron_mm();
  open.triangles.pop_back();
  test::write_ply_ascii(dir / "open.ply", open);
  EXPECT_EQ(load_mesh_file(dir / "open.ply").triangle_count(), 3u);
  expect_error(dir / "open.ply", closed_surface(), "the surface is not closed");
}

TEST(MeshFile, BadTransformIsRefused) {
  const test::TestFolder dir;
  test::write_obj(dir / "t.obj", tetrahedron_mm());
  MeshLoadOptions o;
  o.transform.scale = 0;
  expect_error(dir / "t.obj", o, "positive scale");
}

}  // namespace
}  // namespace imasim::scene
