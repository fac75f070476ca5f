#pragma once
// Checks on a mesh file before and right after Assimp reads it, so that a hostile file is a
// clear MeshFileError instead of an allocation of gigabytes, a hang or a silently absurd mesh:
// the file's size, a PLY header's element counts against the bytes that follow it, the digits
// of an ASCII PLY's numbers, an OBJ's line lengths, and every vertex's coordinates.
#include <cstdint>
#include <string>

struct aiScene;

namespace imasim::scene {

// A heart surface needs tens of thousands of triangles; a binary STL of five million is 250 MB.
constexpr std::uint64_t kMaxMeshFileBytes = std::uint64_t(256) << 20;
// Entries of one PLY element: ten million vertices or faces is far beyond any surface imasim
// steps in real time, and Assimp allocates for the declared count before reading any.
constexpr std::uint64_t kMaxMeshElements = 10'000'000;
// A PLY header is a few hundred bytes; it is read line by line up to this size.
constexpr std::uint64_t kMaxPlyHeaderBytes = 64 << 10;
// An OBJ line holds one vertex, face or statement: 64 KiB is a polygon of thousands of corners.
constexpr std::uint64_t kMaxObjLineBytes = 64 << 10;
// A coordinate in file units: a million millimetres is a kilometre (20-digit numbers are not a
// heart in any unit).
constexpr double kMaxFileCoordinate = 1e6;

// Digits before the point of any number in an ASCII mesh file: a coordinate is at most 10^6 and an
// index below 10^7, and a 32-bit integer property overflows from ten digits on.
constexpr std::uint32_t kMaxMeshIntegerDigits = 9;

// Why the file at `path` (a regular file) is refused before Assimp reads it, or empty.
std::string mesh_file_problem(const std::string& path);

// The first vertex of the imported scene with a non-finite coordinate or one beyond
// kMaxFileCoordinate, as a message ("vertex 3 has a non-finite coordinate"), or empty.
std::string mesh_coordinate_problem(const aiScene& scene);

}  // namespace imasim::scene
