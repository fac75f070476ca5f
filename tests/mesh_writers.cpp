#include "mesh_writers.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <fstream>
#include <sstream>
#include <vector>

namespace imasim::test {

TestFolder::TestFolder() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  path_ = std::filesystem::temp_directory_path() /
          ("imasim_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
           std::to_string(::getpid()));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TestFolder::~TestFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

void write_obj(const std::filesystem::path& path, const geometry::TriangleMesh& mesh) {
  std::ostringstream s;
  s.precision(17);
  s << "# test mesh\n";
  for (const Vec3& v : mesh.vertices)
    s << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& t : mesh.triangles)
    s << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  write_text(path, s.str());
}

namespace {

Vec3 face_normal(const geometry::TriangleMesh& mesh, const geometry::Triangle& t) {
  const Vec3& a = mesh.vertices[t[0]];
  return (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).normalized();
}

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t chunk = std::uint32_t(std::uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) chunk |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) chunk |= std::uint32_t(std::uint8_t(bytes[i + 2]));
    out += table[(chunk >> 18) & 63];
    out += table[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[chunk & 63] : '=';
  }
  return out;
}

}  // namespace

void write_stl_ascii(const std::filesystem::path& path, const geometry::TriangleMesh& mesh) {
  std::ostringstream s;
  s.precision(9);
  s << "solid test\n";
  for (const auto& t : mesh.triangles) {
    const Vec3 n = face_normal(mesh, t);
    s << " facet normal " << n.x() << " " << n.y() << " " << n.z() << "\n  outer loop\n";
    for (std::uint32_t v : t) {
      const Vec3& x = mesh.vertices[v];
      s << "   vertex " << x.x() << " " << x.y() << " " << x.z() << "\n";
    }
    s << "  endloop\n endfacet\n";
  }
  s << "endsolid test\n";
  write_text(path, s.str());
}

void write_stl_binary(const std::filesystem::path& path, const geometry::TriangleMesh& mesh) {
  std::string out(80, ' ');
  out.replace(0, 17, "binary test mesh.");
  put(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    const Vec3 n = face_normal(mesh, t);
    for (int k = 0; k < 3; ++k)
      put(out, float(n[k]));
    for (std::uint32_t v : t)
      for (int k = 0; k < 3; ++k)
        put(out, float(mesh.vertices[v][k]));
    put(out, std::uint16_t(0));
  }
  write_text(path, out);
}

void write_ply_ascii(const std::filesystem::path& path, const geometry::TriangleMesh& mesh) {
  std::ostringstream s;
  s.precision(9);
  s << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertices.size()
    << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
    << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& v : mesh.vertices)
    s << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& t : mesh.triangles)
    s << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  write_text(path, s.str());
}

void write_gltf(const std::filesystem::path& path, const geometry::TriangleMesh& mesh,
                const Vec3& node_translation) {
  std::string buffer;
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    for (int k = 0; k < 3; ++k)
      put(buffer, float(v[k]));
  }
  const std::size_t position_bytes = buffer.size();
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t)
      put(buffer, v);
  std::ostringstream s;
  s.precision(9);
  s << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],)"
    << R"("nodes": [{"mesh": 0, "translation": [)" << node_translation.x() << ", "
    << node_translation.y() << ", " << node_translation.z() << "]}],"
    << R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],)"
    << R"("buffers": [{"byteLength": )" << buffer.size()
    << R"(, "uri": "data:application/octet-stream;base64,)" << base64(buffer) << R"("}],)"
    << R"("bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" << position_bytes
    << R"(, "target": 34962}, {"buffer": 0, "byteOffset": )" << position_bytes
    << R"(, "byteLength": )" << buffer.size() - position_bytes << R"(, "target": 34963}],)"
    << R"("accessors": [{"bufferView": 0, "componentType": 5126, "count": )" << mesh.vertices.size()
    << R"(, "type": "VEC3", "min": [)" << float(lo.x()) << ", " << float(lo.y()) << ", "
    << float(lo.z()) << "], \"max\": [" << float(hi.x()) << ", " << float(hi.y()) << ", "
    << float(hi.z()) << "]}, "
    << R"({"bufferView": 1, "componentType": 5125, "count": )" << mesh.triangles.size() * 3
    << R"(, "type": "SCALAR"}]})";
  write_text(path, s.str());
}

}  // namespace imasim::test
