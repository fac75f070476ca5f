#include "scene/scene_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "math/edit_distance.hpp"
#include "math/printable.hpp"
#include "math/text_file.hpp"
#include "scene/heart_series.hpp"
#include "scene/scene_key_renames.hpp"
#include "scene/scene_keys.hpp"
#include "scene/solver_budget.hpp"
#include "scene/toml_nesting.hpp"

namespace imasim::scene {

SceneFileError::SceneFileError(std::vector<std::string> messages)
    : std::runtime_error([&] {
        std::string all;
        for (const std::string& m : messages)
          all += (all.empty() ? "" : "\n") + m;
        return all;
      }()),
      messages_(std::move(messages)) {}

namespace {

std::string string_text(const std::string& v);  // with the other printers below

// A scene file with every key and its comment is about 10 KB: 100 times that is no scene.
constexpr std::uint64_t kMaxSceneFileBytes = std::uint64_t(1) << 20;
// Keys are echoed in messages cut to this many bytes (a key may be megabytes long).
constexpr std::size_t kShownKeyBytes = 80;
// No "did you mean" for a longer key: the longest valid key has 34 bytes, and the edit distance
// costs its length times the candidate's for each of about 90 candidates.
constexpr std::size_t kMaxSuggestedKeyBytes = 64;
// Messages listed for one file; the rest are counted. A file of thousands of unknown keys is
// not a scene, and listing (and suggesting for) each would take minutes.
constexpr std::size_t kMaxReportedProblems = 20;

std::string shown_key(const std::string& key) {
  return printable(key, kShownKeyBytes);
}

std::string shown_name(const std::string& name) {
  std::string out;
  append_printable(out, name, false);
  return out;
}

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

// One problem found in a file. A "did you mean" suggestion is found only for problems that are
// reported (see kMaxReportedProblems).
struct Problem {
  std::uint32_t line = 0;
  std::string text;            // after "FILE:LINE: "
  std::string unknown;         // a key or table to suggest for; empty: none
  bool unknown_table = false;  // suggest a table rather than a key
};

struct Reader {
  const std::string& file;
  ThoraxSceneParams& params;
  std::vector<Problem> errors;
  std::map<std::string, std::uint32_t> lines;                // line of each key given in the file
  std::vector<std::pair<std::uint32_t, std::string>> notes;  // by line: "key ..."
  // Old keys whose value converts once the whole file is read (it depends on other keys).
  struct Pending {
    const RenamedSceneKey* rename;
    const SceneKey* key;
    double value;
    std::uint32_t line;
  };
  std::vector<Pending> pending;
  std::vector<std::pair<const RenamedSceneKey*, std::uint32_t>> renamed;  // read, and where
  std::set<std::string> given;  // keys given under their own names

  void add(std::uint32_t line, std::string text) {
    errors.push_back({line, std::move(text), {}, false});
  }

  // An error about keys that constrain each other, at the first of them given in the file.
  void cross_error(std::initializer_list<std::string> keys, const std::string& what) {
    for (const std::string& k : keys) {
      if (auto it = lines.find(k); it != lines.end()) {
        add(it->second, "key '" + k + "': " + what);
        return;
      }
    }
    add(1, "key '" + *keys.begin() + "': " + what);
  }

  // Checks across keys, and the files the scene names.
  void check_whole() {
    const Real gap = params.anatomy.ima_depth - params.patch.vessel.radius;
    if (!(gap >= Real(0.0005))) {
      cross_error({"anatomy.ima_depth_m", "vessel.radius_m"},
                  "the IMA must lie at least 0.5 mm inside the chest wall: ima_depth_m " +
                      real_text(params.anatomy.ima_depth) + " <= vessel.radius_m " +
                      real_text(params.patch.vessel.radius) + " + 0.0005");
    }
    const Vec3 axis = params.heart.long_axis, lateral = params.heart.lateral;
    if (!(axis.norm() > 0) ||
        !(axis.cross(lateral).norm() > Real(1e-6) * axis.norm() * lateral.norm())) {
      cross_error({"heart.long_axis", "heart.lateral"},
                  "the heart's long axis must be non-zero and not parallel to its lateral axis");
    }
    check_budget();
    check_fascia_solver();
    if (params.vessel_solver == kImplicitFasciaSolver && lines.count("vessel.coarse"))
      cross_error({"vessel.coarse", "vessel.solver"},
                  "the implicit vessel has no rows in the step's rate bands: vessel.coarse changes "
                  "nothing with it");
    if (!params.heart_series.phase_files.empty()) {
      try {
        load_heart_series(params.heart_series);
      } catch (const MeshFileError& e) {
        cross_error({"heart.phase_files"}, e.what());
      }
    }
  }

  // The implicit solver's law: read by it only (a key that changes nothing is refused), and
  // stiffening, not softening, past the toe.
  void check_fascia_solver() {
    if (params.fascia_solver != kImplicitFasciaSolver) {
      for (const char* key : {"fascia.linear_modulus_pa", "fascia.toe_strain"})
        if (lines.count(key))
          cross_error({key}, "read by the implicit fascia only: set fascia.solver = \"implicit\"");
      return;
    }
    const Real toe = params.patch.fascia.object.membrane->youngs_modulus;
    if (!(params.fascia_linear_modulus >= toe)) {
      cross_error({"fascia.linear_modulus_pa", "fascia.youngs_modulus_pa"},
                  "the linear region's modulus " + real_text(params.fascia_linear_modulus) +
                      " is below the toe's (youngs_modulus_pa " + real_text(toe) +
                      "): collagen stiffens as it is stretched");
    }
  }

  // The solver's sweeps and the scene's size against solver_budget.hpp, at the keys that set
  // what is over its limit.
  void check_budget() {
    const tissue::ThoracicPatchParams& p = params.patch;
    const std::uint64_t particles = estimate_thorax_particles(params);
    const std::string problem = solver_budget_problem(particles, p.solver.substeps,
                                                      p.solver.iterations, "substeps x iterations");
    if (problem.empty()) return;
    const std::uint64_t sweeps = std::uint64_t(p.solver.substeps) * p.solver.iterations;
    if (sweeps > kMaxSweepsPerStep)
      return cross_error({"solver.substeps", "solver.iterations"}, problem);
    std::initializer_list<std::string> counts = {"fascia.nx",
                                                 "fascia.ny",
                                                 "chest_wall.nu",
                                                 "chest_wall.nv",
                                                 "vessel.coarse_rings",
                                                 "vessel.coarse_segments",
                                                 "vessel.fine_rings",
                                                 "vessel.fine_segments",
                                                 "ima_fat.strands_per_face",
                                                 "ima_fat.segments",
                                                 "fascia_fat.strands_per_face",
                                                 "fascia_fat.segments",
                                                 "solver.substeps",
                                                 "solver.iterations"};
    cross_error(counts, problem);
  }

  void error(const toml::node& node, const std::string& path, const std::string& what) {
    error_as(node, "'" + shown_key(path) + "'", what);
  }
  // `shown`: the key as the message names it, quoted.
  void error_as(const toml::node& node, const std::string& shown, const std::string& what) {
    add(node.source().begin.line, "key " + shown + ": " + what);
  }

  // An unknown key or table: its suggestion is looked up when the problem is reported.
  void unknown(const toml::node& node, const std::string& path, bool table, std::string text) {
    Problem p{node.source().begin.line, std::move(text), path, table};
    if (path.size() > kMaxSuggestedKeyBytes) p.unknown.clear();
    errors.push_back(std::move(p));
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

  // Three finite numbers, each in [key.min, key.max].
  std::optional<Vec3> vec3(const toml::node& n, const SceneKey& key) {
    const toml::array* a = n.as_array();
    if (a == nullptr || a->size() != 3) return std::nullopt;
    Vec3 v;
    for (int i = 0; i < 3; ++i) {
      const auto x = number(*a->get(static_cast<std::size_t>(i)));
      if (!x || !(*x >= key.min && *x <= key.max)) return std::nullopt;
      v[i] = Real(*x);
    }
    return v;
  }

  // A path as written, made absolute against the scene file's folder.
  std::string resolve(const std::string& written) const {
    const std::filesystem::path p(written);
    if (p.is_absolute()) return p.lexically_normal().string();
    return std::filesystem::absolute(std::filesystem::path(file).parent_path() / p)
        .lexically_normal()
        .string();
  }

  // `shown`: the key as the file names it (an old name), for messages; empty: the key's own.
  void read(const SceneKey& key, const toml::node& n, const std::string& shown = {}) {
    lines[std::string(key.path)] = n.source().begin.line;
    // How the file names it, in messages: 'key', or 'old' (now 'new').
    const std::string path = shown.empty() ? "'" + shown_key(std::string(key.path)) + "'" : shown;
    std::visit(
        [&](auto ref) {
          using Ref = decltype(ref);
          if constexpr (std::is_same_v<Ref, RealRef>) {
            const auto v = number(n);
            if (!v) return error_as(n, path, "expected a number in " + range(key));
            if (!(*v >= key.min && *v <= key.max)) {
              return error_as(n, path,
                              "expected a number in " + range(key) + ", got " + real_text(*v));
            }
            *ref(params) = Real(*v);
          } else if constexpr (std::is_same_v<Ref, CountRef> || std::is_same_v<Ref, SeedRef>) {
            const auto v = n.value<std::int64_t>();
            if (!n.is_integer() || !v)
              return error_as(n, path, "expected an integer in " + range(key));
            if (double(*v) < key.min || double(*v) > key.max) {
              return error_as(
                  n, path, "expected an integer in " + range(key) + ", got " + std::to_string(*v));
            }
            *ref(params) = static_cast<std::remove_reference_t<decltype(*ref(params))>>(*v);
          } else if constexpr (std::is_same_v<Ref, BoolRef>) {
            if (!n.is_boolean()) return error_as(n, path, "expected true or false");
            *ref(params) = *n.value<bool>();
          } else if constexpr (std::is_same_v<Ref, Vec3Ref>) {
            const auto v = vec3(n, key);
            if (!v) return error_as(n, path, "expected [x, y, z], three numbers in " + range(key));
            *ref(params) = *v;
          } else if constexpr (std::is_same_v<Ref, ChoiceRef>) {
            std::string words;
            for (std::string_view c : key.choices)
              words += (words.empty() ? "\"" : " or \"") + std::string(c) + "\"";
            const auto v = n.value<std::string>();
            if (!n.is_string() || !v) return error_as(n, path, "expected " + words);
            if (std::find(key.choices.begin(), key.choices.end(), *v) == key.choices.end())
              return error_as(n, path, "expected " + words + ", got " + string_text(*v));
            *ref(params) = *v;
          } else if constexpr (std::is_same_v<Ref, NameKeyRef>) {
            const auto v = n.value<std::string>();
            const std::string rule = "a name of " + std::to_string(int(key.min)) + " to " +
                                     std::to_string(int(key.max)) +
                                     " letters, digits, '.', '_' or '-'";
            if (!n.is_string() || !v) return error_as(n, path, "expected " + rule);
            const bool allowed = std::all_of(v->begin(), v->end(), [](char c) {
              return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' ||
                     c == '-';
            });
            if (!allowed || double(v->size()) < key.min || double(v->size()) > key.max)
              return error_as(n, path, "expected " + rule + ", got " + string_text(*v));
            *ref.get(params) = *v;
          } else {
            const toml::array* a = n.as_array();
            if (a == nullptr) return error_as(n, path, "expected an array of file names");
            std::vector<std::string> paths;
            for (std::size_t i = 0; i < a->size(); ++i) {
              const auto v = a->get(i)->value<std::string>();
              if (!a->get(i)->is_string() || !v || v->empty())
                return error_as(n, path, "entry " + std::to_string(i) + " is not a file name");
              paths.push_back(resolve(*v));
            }
            *ref(params) = paths;
          }
        },
        key.ref);
  }

  static const SceneKey& key_named(std::string_view path) {
    for (const SceneKey& k : scene_keys())
      if (k.path == path) return k;
    throw std::logic_error("scene_key_renames.cpp names a key that does not exist");
  }

  // An old key: read under its new name now, or once the file is read when its value converts.
  void read_renamed(const RenamedSceneKey& r, const toml::node& n) {
    const SceneKey& key = key_named(r.new_path);
    const std::uint32_t line = n.source().begin.line;
    const std::string shown =
        "'" + std::string(r.old_path) + "' (now '" + std::string(r.new_path) + "')";
    renamed.emplace_back(&r, line);
    if (r.conversion == KeyConversion::same) {
      const std::size_t before = errors.size();
      read(key, n, shown);
      if (errors.size() == before)
        notes.emplace_back(line, "key '" + std::string(r.old_path) + "' is now '" +
                                     std::string(r.new_path) + "' (" + std::string(r.why) +
                                     "); read as such");
      return;
    }
    const std::optional<double> v = number(n);
    if (!v || !(*v > 0) || !std::isfinite(*v))
      return error_as(n, shown, "expected a length in metres above 0");
    pending.push_back({&r, &key, *v, line});
  }

  // After the whole file: converted values, and an old name given beside its new one.
  void finish_renamed() {
    for (const Pending& p : pending) {
      const Real unit = p.rename->conversion == KeyConversion::per_ima_fat_gap
                            ? params.anatomy.ima_depth - params.patch.vessel.radius
                            : params.anatomy.fat_thickness;
      const double v = p.value / double(unit);
      const std::string old_path(p.rename->old_path), new_path(p.rename->new_path);
      if (!(unit > 0) || !(v >= p.key->min && v <= p.key->max)) {
        add(p.line, "key '" + old_path + "' (now '" + new_path + "', " +
                        std::string(p.rename->why) + "): " + real_text(p.value) + " m is " +
                        real_text(v) + " of " + real_text(double(unit)) + " m, outside " +
                        range(*p.key));
        continue;
      }
      *std::get<RealRef>(p.key->ref)(params) = Real(v);
      lines[new_path] = p.line;
      notes.emplace_back(p.line, "key '" + old_path + "' is now '" + new_path + "' (" +
                                     std::string(p.rename->why) + "); " + real_text(p.value) +
                                     " m read as " + real_text(v));
    }
    for (const auto& [r, line] : renamed) {
      if (given.count(std::string(r->new_path)) > 0)
        add(line, "key '" + std::string(r->old_path) + "' is the old name of '" +
                      std::string(r->new_path) + "', which the file also gives: keep one");
    }
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
          unknown(node, path, true, "unknown table '" + shown_key(path) + "'");
        } else {
          unknown(node, path, false, "key '" + shown_key(path) + "': not inside a table");
        }
        continue;
      }
      const SceneKey* key = nullptr;
      for (const SceneKey& candidate : scene_keys()) {
        if (candidate.path == path) key = &candidate;
      }
      if (key == nullptr) {
        if (const RenamedSceneKey* renamed_key = find_renamed_scene_key(path)) {
          read_renamed(*renamed_key, node);
        } else if (const RetiredSceneKey* retired = find_retired_scene_key(path)) {
          add(node.source().begin.line,
              "key '" + path + "' was retired; instead: " + std::string(retired->instead));
        } else {
          unknown(node, path, false, "key '" + shown_key(path) + "': unknown key");
        }
        continue;
      }
      given.insert(path);
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

// A TOML basic string: quotes and backslashes escaped, control characters as \u and four hex
// digits.
std::string string_text(const std::string& v) {
  std::string out = "\"";
  for (char c : v) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      std::array<char, 8> code;
      std::snprintf(code.data(), code.size(), "\\u%04x", static_cast<unsigned char>(c));
      out += code.data();
      continue;
    }
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

ThoraxSceneParams parse_scene(const std::string& text, const std::string& name) {
  const std::string shown_file = shown_name(name);
  if (const TomlNestingProblem deep = find_deep_toml_nesting(text); deep.line > 0)
    throw SceneFileError({shown_file + ":" + std::to_string(deep.line) + ": " + deep.what});
  ThoraxSceneParams params = default_thorax_scene_params();
  toml::table table;
  try {
    table = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    // The description may quote a key from the file: shown escaped and cut short.
    constexpr std::size_t kShownDescriptionBytes = 200;
    throw SceneFileError({shown_file + ":" + std::to_string(e.source().begin.line) + ": " +
                          printable(e.description(), kShownDescriptionBytes)});
  }
  Reader reader{name, params, {}, {}, {}, {}, {}, {}};
  reader.walk(table, "");
  reader.finish_renamed();
  if (reader.errors.empty()) reader.check_whole();
  if (reader.errors.empty()) {
    std::stable_sort(reader.notes.begin(), reader.notes.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [line, note] : reader.notes)
      params.file_notes.push_back(shown_file + ":" + std::to_string(line) + ": " + note);
    return params;
  }
  // toml++ visits keys in sorted order; report in file order.
  std::stable_sort(reader.errors.begin(), reader.errors.end(),
                   [](const Problem& x, const Problem& y) { return x.line < y.line; });
  std::vector<std::string> messages;
  for (std::size_t i = 0; i < reader.errors.size() && i < kMaxReportedProblems; ++i) {
    const Problem& p = reader.errors[i];
    std::string m = shown_file + ":" + std::to_string(p.line) + ": " + p.text;
    if (!p.unknown.empty()) m += "; did you mean '" + nearest(p.unknown, p.unknown_table) + "'?";
    messages.push_back(std::move(m));
  }
  if (reader.errors.size() > kMaxReportedProblems) {
    messages.push_back(shown_file + ": " +
                       std::to_string(reader.errors.size() - kMaxReportedProblems) +
                       " more problems not listed (the first " +
                       std::to_string(kMaxReportedProblems) + " are above)");
  }
  throw SceneFileError(messages);
}

ThoraxSceneParams load_scene_file(const std::string& path) {
  const TextFile file = read_text_file(path, kMaxSceneFileBytes, "scene file");
  if (!file.error.empty()) throw SceneFileError({shown_name(path) + ": " + file.error});
  return parse_scene(file.text, path);
}

namespace {

// The implicit fascia's law is read by it only (check_fascia_solver), the vessel's rate band by
// the XPBD vessel only.
bool key_is_read(const ThoraxSceneParams& params, std::string_view path) {
  if (path == "fascia.linear_modulus_pa" || path == "fascia.toe_strain")
    return params.fascia_solver == kImplicitFasciaSolver;
  if (path == "vessel.coarse") return params.vessel_solver != kImplicitFasciaSolver;
  return true;
}

}  // namespace

std::string print_scene(const ThoraxSceneParams& const_params) {
  ThoraxSceneParams params = const_params;  // the key accessors take a mutable reference
  std::ostringstream out;
  out << "# imasim thorax scene. Units are in the key names; every key is optional.\n";
  for (std::string_view table : scene_tables()) {
    out << "\n[" << table << "]\n";
    for (const SceneKey& key : scene_keys()) {
      if (key.path.substr(0, table.size() + 1) != std::string(table) + ".") continue;
      // A key its scene does not read is shown, commented out (given, it would be refused).
      if (!key_is_read(params, key.path)) out << "# ";
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
            } else if constexpr (std::is_same_v<Ref, ChoiceRef>) {
              out << string_text(*ref(params));
            } else if constexpr (std::is_same_v<Ref, NameKeyRef>) {
              out << string_text(*ref.get(params));
            } else {
              out << "[";
              const std::vector<std::string>& paths = *ref(params);
              for (std::size_t i = 0; i < paths.size(); ++i)
                out << (i ? ", " : "") << string_text(paths[i]);
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
