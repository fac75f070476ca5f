#include "scene/mesh_file_limits.hpp"

#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "math/printable.hpp"
#include "math/text_file.hpp"

namespace imasim::scene {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Bytes of one PLY scalar type, 0 if unknown.
std::uint64_t ply_type_bytes(std::string_view type) {
  constexpr std::array<std::pair<std::string_view, std::uint64_t>, 16> kTypes = {{
      {"char", 1},
      {"int8", 1},
      {"uchar", 1},
      {"uint8", 1},
      {"short", 2},
      {"int16", 2},
      {"ushort", 2},
      {"uint16", 2},
      {"int", 4},
      {"int32", 4},
      {"uint", 4},
      {"uint32", 4},
      {"float", 4},
      {"float32", 4},
      {"double", 8},
      {"float64", 8},
  }};
  for (const auto& [name, bytes] : kTypes)
    if (name == type) return bytes;
  return 0;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;)
    out.push_back(w);
  return out;
}

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t min_bytes = 0;  // the fewest bytes one entry can take
};

// Why a header line is not PLY as the format defines it, or empty. Assimp's reader is lax: on
// a header it half understands it can read for ever (found by fuzzing), so every line must be
// one the format defines before Assimp sees the file.
std::string ply_line_problem(const std::vector<std::string>& w, std::uint64_t line_number) {
  const auto known = [](const std::string& type) { return ply_type_bytes(type) > 0; };
  const std::string& key = w[0];
  bool ok = false;
  if (key == "format") {
    ok = w.size() == 3 &&
         (w[1] == "ascii" || w[1] == "binary_little_endian" || w[1] == "binary_big_endian") &&
         w[2] == "1.0";
  } else if (key == "comment" || key == "obj_info") {
    ok = true;
  } else if (key == "element") {
    ok = w.size() == 3;
  } else if (key == "property") {
    ok = (w.size() == 3 && known(w[1])) ||
         (w.size() == 5 && w[1] == "list" && known(w[2]) && known(w[3]));
  }
  if (ok) return {};
  std::string shown;
  for (const std::string& word : w)
    shown += (shown.empty() ? "" : " ") + word;
  return "PLY header line " + std::to_string(line_number) + ": not a PLY header line ('" +
         printable(shown, 80) +
         "'; expected format, element, property, comment, obj_info or end_header)";
}

// The integer part of each number in a text, one character at a time: the significant digits of
// a digit run that starts a number (not a fraction's or an exponent's). Assimp reads an ASCII
// PLY's integer properties into 32 bits without a check, so 4294967297 became 1 and passed.
class IntegerPartScan {
 public:
  // Feeds one character; the significant digits of the integer part it is in (0 outside one).
  std::uint32_t feed(char c) {
    if (c >= '0' && c <= '9') {
      if (counting_ && (digits_ > 0 || c != '0')) ++digits_;
    } else {
      const bool exponent_sign = (c == '+' || c == '-') && (previous_ == 'e' || previous_ == 'E');
      counting_ = !(c == '.' || c == 'e' || c == 'E' || exponent_sign);
      digits_ = 0;
    }
    previous_ = c;
    return digits_;
  }

 private:
  bool counting_ = true;
  char previous_ = ' ';
  std::uint32_t digits_ = 0;
};

// An ASCII PLY body's numbers, after the header's `line` lines: none may have more integer
// digits than a coordinate (at most kMaxFileCoordinate) or an index (below kMaxMeshElements)
// can.
std::string ply_body_problem(std::ifstream& in, std::uint64_t line) {
  std::array<char, 1 << 16> buffer;
  IntegerPartScan scan;
  std::string number;
  while (in) {
    in.read(buffer.data(), buffer.size());
    const std::streamsize got = in.gcount();
    for (std::streamsize i = 0; i < got; ++i) {
      const char c = buffer[static_cast<std::size_t>(i)];
      if (c == '\n') ++line;
      const std::uint32_t digits = scan.feed(c);
      if (digits == 0) {
        number.clear();
        continue;
      }
      number += c;
      if (digits > kMaxMeshIntegerDigits)
        return "PLY line " + std::to_string(line) + ": a number with more than " +
               std::to_string(kMaxMeshIntegerDigits) + " digits before its point (" + number +
               "...), beyond any coordinate or index of a mesh (integer properties that long "
               "overflow as they are read)";
    }
  }
  return {};
}

// Each element's declared count against the bytes after the header: an entry takes at least
// its fixed-size properties (binary) or two bytes per property (ASCII: a digit and a
// separator). Every header line must be one the format defines.
std::string ply_problem(const std::string& path, std::uint64_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::uint64_t header_bytes = 0, line_number = 0;
  bool binary = false;
  std::vector<PlyElement> elements;
  while (true) {
    line.clear();
    // Line by line, never more than the header's limit in all.
    for (char c; header_bytes < kMaxPlyHeaderBytes && in.get(c);) {
      ++header_bytes;
      if (c == '\n') break;
      line += c;
    }
    ++line_number;
    if (header_bytes >= kMaxPlyHeaderBytes)
      return "PLY header: no end_header in the first " + size_text(kMaxPlyHeaderBytes);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::vector<std::string> w = words(line);
    if (line_number == 1 && (w.size() != 1 || w[0] != "ply"))
      return "PLY header line 1: expected 'ply' (not a PLY file)";
    if (!in) return "PLY header: the file ends before end_header";
    if (line_number == 1) continue;
    if (w.empty()) continue;
    if (w[0] == "end_header" && w.size() == 1) break;
    if (std::string problem = ply_line_problem(w, line_number); !problem.empty()) return problem;
    if (w[0] == "format") binary = w[1] != "ascii";
    if (w[0] == "element") {
      PlyElement e{w[1], 0, 0};
      const char* end = w[2].data() + w[2].size();
      const auto [ptr, ec] = std::from_chars(w[2].data(), end, e.count);
      if (ec != std::errc() || ptr != end)
        return "PLY header: element '" + printable(w[1], 80) + "' has no valid count (" +
               printable(w[2], 80) + ")";
      if (e.count > kMaxMeshElements)
        return "PLY header: element '" + printable(w[1], 80) + "' declares " + w[2] +
               " entries, above the limit of " + std::to_string(kMaxMeshElements);
      elements.push_back(e);
    }
    if (w[0] == "property") {
      if (elements.empty())
        return "PLY header line " + std::to_string(line_number) + ": a property before any element";
      // "property TYPE NAME" or "property list COUNT_TYPE ITEM_TYPE NAME"; an empty list takes
      // its count only.
      const std::string_view type = w[1] == "list" ? w[2] : w[1];
      elements.back().min_bytes += binary ? std::max<std::uint64_t>(ply_type_bytes(type), 1) : 2;
    }
  }
  const std::uint64_t body = file_bytes - header_bytes;
  std::uint64_t needed = 0;
  for (const PlyElement& e : elements) {
    // Both factors are at most 10^7 and 8 x the property count: no overflow.
    needed += e.count * e.min_bytes;
    if (needed > body)
      return "PLY header: element '" + e.name + "' declares " + std::to_string(e.count) +
             " entries, which with those before it need at least " + std::to_string(needed) +
             " bytes, but the file has " + std::to_string(body) + " after its header";
  }
  return binary ? std::string() : ply_body_problem(in, line_number + 1);
}

std::string obj_problem(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 1 << 16> buffer;
  std::uint64_t line = 1, length = 0;
  while (in) {
    in.read(buffer.data(), buffer.size());
    const std::streamsize got = in.gcount();
    for (std::streamsize i = 0; i < got; ++i) {
      if (buffer[static_cast<std::size_t>(i)] == '\n') {
        ++line, length = 0;
      } else if (++length > kMaxObjLineBytes) {
        return "line " + std::to_string(line) + " is longer than " + size_text(kMaxObjLineBytes) +
               " (an OBJ line holds one vertex or face)";
      }
    }
  }
  return {};
}

}  // namespace

std::string mesh_file_problem(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec) return "cannot read the mesh: " + ec.message();
  if (bytes > kMaxMeshFileBytes)
    return "the mesh file is " + std::to_string(bytes) + " bytes, above the limit of " +
           size_text(kMaxMeshFileBytes);
  const std::string ext = lower_extension(path);
  if (ext == ".ply") return ply_problem(path, bytes);
  if (ext == ".obj") return obj_problem(path);
  return {};
}

std::string mesh_coordinate_problem(const aiScene& scene) {
  std::uint64_t index = 0;  // over all meshes, in the order the loader welds them
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    for (unsigned v = 0; v < mesh.mNumVertices; ++v, ++index) {
      const aiVector3D& p = mesh.mVertices[v];
      for (const float x : {p.x, p.y, p.z}) {
        if (!std::isfinite(x))
          return "vertex " + std::to_string(index) + " has a non-finite coordinate";
        if (std::abs(double(x)) > kMaxFileCoordinate) {
          std::ostringstream s;
          s << "vertex " << index << " has a coordinate of " << x
            << " file units, beyond the limit of " << kMaxFileCoordinate
            << " (a kilometre in millimetres)";
          return s.str();
        }
      }
    }
  }
  return {};
}

}  // namespace imasim::scene
