#pragma once
// Every parameter of the thorax scene as a scene-file key: its dotted path (the unit in the
// name), where it lives in ThoraxSceneParams, its valid range and a one-line description. This
// one table drives parsing, validation, "did you mean" suggestions and `scene print-default`.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "scene/thorax_scene.hpp"

namespace imasim::scene {

using RealRef = Real* (*)(ThoraxSceneParams&);
using CountRef = std::uint32_t* (*)(ThoraxSceneParams&);
using SeedRef = std::uint64_t* (*)(ThoraxSceneParams&);
using BoolRef = bool* (*)(ThoraxSceneParams&);
using Vec3Ref = Vec3* (*)(ThoraxSceneParams&);
using PathListRef = std::vector<std::string>* (*)(ThoraxSceneParams&);  // file paths
using ChoiceRef = std::string* (*)(ThoraxSceneParams&);  // one of the key's `choices`
// A name (an OpenIGTLink device name, an IPv4 address): letters, digits and . _ -, of a length
// in [min, max].
using NameRef = std::string* (*)(ThoraxSceneParams&);
struct NameKeyRef {
  NameRef get;
};

struct SceneKey {
  std::string_view path;  // "table.key"
  std::variant<RealRef, CountRef, SeedRef, BoolRef, Vec3Ref, PathListRef, ChoiceRef, NameKeyRef>
      ref;
  double min = 0, max = 0;  // inclusive range for numbers and each component of a vector
  std::string_view doc;
  std::span<const std::string_view> choices = {};  // the words a ChoiceRef key accepts
};

std::span<const SceneKey> scene_keys();

// The tables, in file order.
std::span<const std::string_view> scene_tables();

}  // namespace imasim::scene
