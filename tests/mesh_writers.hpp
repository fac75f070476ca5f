#pragma once
// Writers of small test meshes in each format imasim reads (OBJ, ASCII and binary STL, ASCII
// PLY, glTF 2.0 with an embedded buffer), so that tests need no data files.
#include <cstdint>
#include <filesystem>
#include <string>

#include "geometry/triangle_mesh.hpp"

namespace imasim::test {

// A fresh, empty folder for one test's files (named after the running test), removed with
// everything in it when the test ends.
class TestFolder {
 public:
  TestFolder();
  ~TestFolder();
  TestFolder(const TestFolder&) = delete;
  TestFolder& operator=(const TestFolder&) = delete;
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

void write_obj(const std::filesystem::path& path, const geometry::TriangleMesh& mesh);
void write_stl_ascii(const std::filesystem::path& path, const geometry::TriangleMesh& mesh);
void write_stl_binary(const std::filesystem::path& path, const geometry::TriangleMesh& mesh);
void write_ply_ascii(const std::filesystem::path& path, const geometry::TriangleMesh& mesh);
// `node_translation` goes into the glTF node, so loading must apply node transforms.
void write_gltf(const std::filesystem::path& path, const geometry::TriangleMesh& mesh,
                const Vec3& node_translation = Vec3::Zero());
void write_text(const std::filesystem::path& path, const std::string& text);

}  // namespace imasim::test
