// Mesh files from the red team's hostile set: a PLY header declaring billions of
// entries (std::bad_alloc or a hang in Assimp), an OBJ with a megabyte line or 20-digit numbers,
// a NaN vertex (reported as "joins 2 separate fans"), and phase meshes scaled to kilometres or
// below a micron. Each is a MeshFileError naming the file and the cause, found quickly.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "mesh_writers.hpp"
#include "scene/heart_series.hpp"
#include "scene/mesh_file.hpp"

namespace imasim::scene {
namespace {

void expect_refused(const std::filesystem::path& path, const std::string& expected) {
  const auto start = std::chrono::steady_clock::now();
  try {
    load_mesh_file(path);
    ADD_FAILURE() << path << " loaded; expected: " << expected;
  } catch (const MeshFileError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": " + expected);
  }
  // A hang guard, not a benchmark: what it guards against (a search or a parse that grows with
  // the hostile input) takes minutes, so the bound stays far from the sanitizers' and a loaded
  // machine's slowdown (1.1 s once under ASan beside a build).
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}

const char* const kTetrahedronObj =
    "v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

std::string tetrahedron_with(const std::string& second_vertex) {
  std::string text = kTetrahedronObj;
  text.replace(text.find("v 10 0 0"), 8, second_vertex);
  return text;
}

// Files the fuzzer found (fuzz/corpus/mesh_ply/regression_*): Debian's Assimp aborted on a
// failed internal check, died of a bus error in its triangulation, and read for ever on a header
// it half understood. Each is now a MeshFileError, quickly.
TEST(MeshFileHostile, FilesThatCrashedOrHungTheImporterAreRefused) {
  const std::string dir = IMASIM_SOURCE_DIR "/fuzz/corpus/mesh_ply/";
  expect_refused(dir + "regression_lax_header_hang.ply",
                 "PLY header line 2: not a PLY header line ('format binary_l\\x9eittle_endian "
                 "1.0'; expected format, element, property, comment, obj_info or end_header)");
  for (const char* name : {"regression_assimp_assertion.ply", "regression_assimp_bus_error.ply"}) {
    try {
      load_mesh_file(dir + name);
      ADD_FAILURE() << name << " loaded";
    } catch (const MeshFileError& e) {
      EXPECT_NE(std::string(e.what()).find(dir + name + ": cannot read the mesh: "),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(MeshFileHostile, PlyHeadersMustBeWhatTheFormatDefines) {
  const test::TestFolder dir;
  const std::string vertices =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string faces = "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  test::write_text(dir / "no_end.ply", "ply\nformat ascii 1.0\n" + vertices + faces);
  expect_refused(dir / "no_end.ply", "PLY header: the file ends before end_header");
  test::write_text(dir / "not_ply.ply",
                   "plx\nformat ascii 1.0\n" + vertices + faces + "end_header\n" + body);
  expect_refused(dir / "not_ply.ply", "PLY header line 1: expected 'ply' (not a PLY file)");
  test::write_text(dir / "typo.ply", "ply\nformat ascii 1.0\n" + vertices + "elemnt face 1\n" +
                                         "end_header\n" + body);
  expect_refused(dir / "typo.ply",
                 "PLY header line 7: not a PLY header line ('elemnt face 1'; expected format, "
                 "element, property, comment, obj_info or end_header)");
  test::write_text(dir / "type.ply",
                   "ply\nformat ascii 1.0\nelement vertex 3\n"
                   "property real x\nend_header\n" +
                       body);
  expect_refused(dir / "type.ply",
                 "PLY header line 4: not a PLY header line ('property real x'; expected format, "
                 "element, property, comment, obj_info or end_header)");
  test::write_text(dir / "orphan.ply",
                   "ply\nformat ascii 1.0\nproperty float x\n" + vertices + "end_header\n");
  expect_refused(dir / "orphan.ply", "PLY header line 3: a property before any element");
  // Comments, obj_info and CRLF line ends are PLY: an open triangle loads (no closed surface
  // asked for).
  test::write_text(dir / "ok.ply",
                   "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\n"
                   "obj_info a triangle\r\n" +
                       vertices + faces + "end_header\r\n" + body);
  const geometry::TriangleMesh triangle = load_mesh_file(dir / "ok.ply");
  EXPECT_EQ(triangle.vertex_count(), 3u);
  EXPECT_EQ(triangle.triangle_count(), 1u);
}

TEST(MeshFileHostile, PlyCountsAreCheckedAgainstTheFileSize) {
  const test::TestFolder dir;
  const std::string header_tail =
      "property float x\nproperty float y\nproperty float z\nelement face 4\n"
      "property list uchar int vertex_indices\nend_header\n";
  test::write_text(dir / "huge.ply",
                   "ply\nformat ascii 1.0\nelement vertex 4000000000\n" + header_tail + "0 0 0\n");
  expect_refused(dir / "huge.ply",
                 "PLY header: element 'vertex' declares 4000000000 entries, above the limit of "
                 "10000000");
  test::write_text(dir / "short.ply",
                   "ply\nformat binary_little_endian 1.0\nelement vertex 5000000\n" + header_tail +
                       std::string(24, '\0'));
  expect_refused(dir / "short.ply",
                 "PLY header: element 'vertex' declares 5000000 entries, which with those before "
                 "it need at least 60000000 bytes, but the file has 24 after its header");
  test::write_text(
      dir / "faces.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\n" +
          std::string(header_tail).replace(header_tail.find("face 4"), 6, "face 9999999") +
          "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expect_refused(dir / "faces.ply",
                 "PLY header: element 'face' declares 9999999 entries, which with those before it "
                 "need at least 20000016 bytes, but the file has 26 after its header");
  test::write_text(dir / "endless.ply", "ply\nformat ascii 1.0\n" + std::string(70000, 'c'));
  expect_refused(dir / "endless.ply", "PLY header: no end_header in the first 64 KiB");
}

// Assimp reads an ASCII PLY's int properties into 32 bits unchecked: 4294967297 was read as 1, a
// vertex in range, and the file loaded. Numbers with ten or more digits before their point are
// refused before it reads them; long fractions, exponents and leading zeros are numbers as usual.
TEST(MeshFileHostile, PlyNumbersTooLongForAnyCoordinateOrIndexAreRefused) {
  const test::TestFolder dir;
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty int x\nproperty int y\nproperty int z\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  test::write_text(dir / "wraps.ply", header + "0 0 0\n4294967297 0 0\n0 10 0\n0 0 10\n" + faces);
  expect_refused(dir / "wraps.ply",
                 "PLY line 11: a number with more than 9 digits before its point (4294967297...), "
                 "beyond any coordinate or index of a mesh (integer properties that long overflow "
                 "as they are read)");
  test::write_text(
      dir / "index.ply",
      header + "0 0 0\n10 0 0\n0 10 0\n0 0 10\n3 0 2 -12345678901234567890\n" + faces.substr(8));
  expect_refused(dir / "index.ply",
                 "PLY line 14: a number with more than 9 digits before its point (1234567890...), "
                 "beyond any coordinate or index of a mesh (integer properties that long overflow "
                 "as they are read)");
  std::string floats = header;
  for (const char* axis : {"x", "y", "z"})
    floats.replace(floats.find(std::string("int ") + axis), 4 + 1, std::string("float ") + axis);
  test::write_text(dir / "fine.ply", floats +
                                         "0.0000000000000000001 0 0\n10.12345678901234567890 0 "
                                         "0\n0 1.0e+1 0\n0 0 00000000010\n" +
                                         faces);
  EXPECT_EQ(load_mesh_file(dir / "fine.ply").vertices.size(), 4u);
}

TEST(MeshFileHostile, ObjLinesAndCoordinatesAreBounded) {
  const test::TestFolder dir;
  test::write_text(dir / "long.obj", tetrahedron_with("v 10 0 0 " + std::string(1 << 20, '9')));
  expect_refused(dir / "long.obj",
                 "line 2 is longer than 64 KiB (an OBJ line holds one vertex or face)");
  test::write_text(dir / "digits.obj", tetrahedron_with("v 12345678901234567890 0 0"));
  expect_refused(dir / "digits.obj",
                 "vertex 2 has a coordinate of 1.23457e+19 file units, beyond the limit of "
                 "1e+06 (a kilometre in millimetres)");
}

TEST(MeshFileHostile, NonFiniteVertexIsNamed) {
  const test::TestFolder dir;
  test::write_text(dir / "nan.obj", tetrahedron_with("v nan 0 0"));
  expect_refused(dir / "nan.obj", "vertex 2 has a non-finite coordinate");
  test::write_text(dir / "inf.obj", tetrahedron_with("v 10 inf 0"));
  expect_refused(dir / "inf.obj", "vertex 2 has a non-finite coordinate");
}

TEST(MeshFileHostile, LargeFilesAreRefusedUnread) {
  const test::TestFolder dir;
  const std::filesystem::path big = dir / "big.stl";
  test::write_text(big, "solid x\n");
  std::filesystem::resize_file(big, (std::uint64_t(256) << 20) + 1);  // sparse
  expect_refused(big, "the mesh file is 268435457 bytes, above the limit of 256 MiB");
}

TEST(MeshFileHostile, HeartsOfAbsurdSizeAreRefused) {
  const test::TestFolder dir;
  test::write_text(dir / "p0.obj", kTetrahedronObj);
  test::write_text(dir / "p1.obj", kTetrahedronObj);
  const std::vector<std::string> files = {(dir / "p0.obj").string(), (dir / "p1.obj").string()};
  for (const auto& [scale, size] : {std::pair{1e3, "10000"}, std::pair{1e-6, "1e-05"}}) {
    HeartSeriesSpec spec{files, {}};
    spec.transform.scale = scale;
    try {
      load_heart_series(spec);
      ADD_FAILURE() << "scale " << scale << " accepted";
    } catch (const MeshFileError& e) {
      EXPECT_EQ(std::string(e.what()), files[0] + ": the heart is " + size +
                                           " m across after heart.mesh_scale; expected 0.005 "
                                           "to 0.5 m (is the mesh_scale right for the file's "
                                           "unit? 0.001: mm)");
    }
  }
}

}  // namespace
}  // namespace imasim::scene
