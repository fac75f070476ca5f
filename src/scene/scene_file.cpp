#include "scene/scene_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "scene/scene_keys.hpp"

namespace imasim::scene {

SceneFileError::SceneFileError(std::vector<std::string> messages)
    : std::runtime_error([&] {
        std::string all;
        for (const std::string& m : messages)
          all += (all.empty() ? "" : "\n") + m;
        return all;
      }()),
      messages_(std::move(messages)) {}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

namespace {

std::string nearest(const std::string& path, bool tables) {
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  auto consider = [&](std::string_view candidate) {
    const std::size_t d = edit_distance(path, std::string(candidate));
    if (d < best_d) best_d = d, best = candidate;
  };
  if (tables) {
    for (std::string_view t : scene_tables())
      consider(t);
  } else {
    for (const SceneKey& k : scene_keys())
      consider(k.path);
  }
  return best;
}

std::string real_text(double v);

struct Reader {
  const std::string& file;
  ThoraxSceneParams& params;
  std::vector<std::string> errors;

  void error(const toml::node& node, const std::string& path, const std::string& what) {
    errors.push_back(file + ":" + std::to_string(node.source().begin.line) + ": key '" + path +
                     "': " + what);
  }

  static std::string range(const SceneKey& k) {
    std::ostringstream s;
    s << "[" << k.min << ", " << k.max << "]";
    return s.str();
  }

  std::optional<double> number(const toml::node& n) {
    if (auto v = n.value<double>(); v && (n.is_floating_point() || n.is_integer())) return v;
    return std::nullopt;
  }

  std::optional<Vec3> vec3(const toml::node& n) {
    const toml::array* a = n.as_array();
    if (a == nullptr || a->size() != 3) return std::nullopt;
    Vec3 v;
    for (int i = 0; i < 3; ++i) {
      const auto x = number(*a->get(static_cast<std::size_t>(i)));
      if (!x || !std::isfinite(*x)) return std::nullopt;
      v[i] = Real(*x);
    }
    return v;
  }

  void read(const SceneKey& key, const toml::node& n) {
    const std::string path(key.path);
    std::visit(
        [&](auto ref) {
          using Ref = decltype(ref);
          if constexpr (std::is_same_v<Ref, RealRef>) {
            const auto v = number(n);
            if (!v) return error(n, path, "expected a number in " + range(key));
            if (!(*v >= key.min && *v <= key.max)) {
              return error(n, path,
                           "expected a number in " + range(key) + ", got " + real_text(*v));
            }
            *ref(params) = Real(*v);
          } else if constexpr (std::is_same_v<Ref, CountRef> || std::is_same_v<Ref, SeedRef>) {
            const auto v = n.value<std::int64_t>();
            if (!n.is_integer() || !v)
              return error(n, path, "expected an integer in " + range(key));
            if (double(*v) < key.min || double(*v) > key.max) {
              return error(n, path,
                           "expected an integer in " + range(key) + ", got " + std::to_string(*v));
            }
            *ref(params) = static_cast<std::remove_reference_t<decltype(*ref(params))>>(*v);
          } else if constexpr (std::is_same_v<Ref, BoolRef>) {
            if (!n.is_boolean()) return error(n, path, "expected true or false");
            *ref(params) = *n.value<bool>();
          } else if constexpr (std::is_same_v<Ref, Vec3Ref>) {
            const auto v = vec3(n);
            if (!v) return error(n, path, "expected [x, y, z], three finite numbers");
            *ref(params) = *v;
          } else {
            const toml::array* a = n.as_array();
            std::vector<Vec3> points;
            for (std::size_t i = 0; a != nullptr && i < a->size(); ++i) {
              const auto v = vec3(*a->get(i));
              if (!v) return error(n, path, "point " + std::to_string(i) + " is not [x, y, z]");
              points.push_back(*v);
            }
            if (points.size() < 2) return error(n, path, "expected at least two [x, y, z] points");
            *ref(params) = points;
          }
        },
        key.ref);
  }

  void walk(const toml::table& table, const std::string& prefix) {
    for (auto&& [k, node] : table) {
      const std::string path =
          prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
      if (prefix.empty()) {
        const toml::table* sub = node.as_table();
        const bool known =
            std::find(scene_tables().begin(), scene_tables().end(), path) != scene_tables().end();
        if (sub != nullptr && known) {
          walk(*sub, path);
        } else if (sub != nullptr) {
          errors.push_back(file + ":" + std::to_string(node.source().begin.line) +
                           ": unknown table '" + path + "'; did you mean '" + nearest(path, true) +
                           "'?");
        } else {
          error(node, path, "not inside a table; did you mean '" + nearest(path, false) + "'?");
        }
        continue;
      }
      const SceneKey* key = nullptr;
      for (const SceneKey& candidate : scene_keys()) {
        if (candidate.path == path) key = &candidate;
      }
      if (key == nullptr) {
        error(node, path, "unknown key; did you mean '" + nearest(path, false) + "'?");
        continue;
      }
      read(*key, node);
    }
  }
};

// A number TOML reads back exactly as a float (always with a '.' or an exponent).
std::string real_text(double v) {
  std::array<char, 64> buffer;  // shortest text that reads back to the same double
  const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v).ptr;
  std::string t(buffer.data(), end);
  if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
  return t;
}

std::string vec3_text(const Vec3& v) {
  std::string out = "[";
  out += real_text(v.x());
  out += ", ";
  out += real_text(v.y());
  out += ", ";
  out += real_text(v.z());
  out += "]";
  return out;
}

}  // namespace

ThoraxSceneParams parse_scene(const std::string& text, const std::string& name) {
  ThoraxSceneParams params = default_thorax_scene_params();
  toml::table table;
  try {
    table = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    throw SceneFileError(
        {name + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description())});
  }
  Reader reader{name, params, {}};
  reader.walk(table, "");
  // toml++ visits keys in sorted order; report in file order.
  std::stable_sort(
      reader.errors.begin(), reader.errors.end(), [&](const std::string& x, const std::string& y) {
        return std::stoul(x.substr(name.size() + 1)) < std::stoul(y.substr(name.size() + 1));
      });
  if (!reader.errors.empty()) throw SceneFileError(reader.errors);
  return params;
}

ThoraxSceneParams load_scene_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneFileError({path + ": cannot open the scene file"});
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path);
}

std::string print_scene(const ThoraxSceneParams& const_params) {
  ThoraxSceneParams params = const_params;  // the key accessors take a mutable reference
  std::ostringstream out;
  out << "# imasim thorax scene. Units are in the key names; every key is optional.\n";
  for (std::string_view table : scene_tables()) {
    out << "\n[" << table << "]\n";
    for (const SceneKey& key : scene_keys()) {
      if (key.path.substr(0, table.size() + 1) != std::string(table) + ".") continue;
      out << key.path.substr(table.size() + 1) << " = ";
      std::visit(
          [&](auto ref) {
            using Ref = decltype(ref);
            if constexpr (std::is_same_v<Ref, RealRef>) {
              out << real_text(double(*ref(params)));
            } else if constexpr (std::is_same_v<Ref, CountRef> || std::is_same_v<Ref, SeedRef>) {
              out << *ref(params);
            } else if constexpr (std::is_same_v<Ref, BoolRef>) {
              out << (*ref(params) ? "true" : "false");
            } else if constexpr (std::is_same_v<Ref, Vec3Ref>) {
              out << vec3_text(*ref(params));
            } else {
              out << "[";
              const std::vector<Vec3>& points = *ref(params);
              for (std::size_t i = 0; i < points.size(); ++i)
                out << (i ? ", " : "") << vec3_text(points[i]);
              out << "]";
            }
          },
          key.ref);
      out << "  # " << key.doc << "\n";
    }
  }
  return out.str();
}

}  // namespace imasim::scene
