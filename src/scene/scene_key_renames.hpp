#pragma once
// Keys of earlier scene files: a key that was renamed is read under its new name with a
// note naming it, its value converted where the unit changed; a key whose quantity no longer
// exists (the scene is laid out from the anatomy now, materials are moduli, not compliances) is
// refused naming what replaced it. Scene files that loaded before keep loading, or say why not.
#include <span>
#include <string_view>

namespace imasim::scene {

// How an old value becomes the new key's.
enum class KeyConversion : unsigned char {
  same,               // the same quantity and number
  per_ima_fat_gap,    // a length (m) as a multiple of the vessel-to-wall gap
  per_fat_thickness,  // a length (m) as a multiple of the wall-to-fascia fat thickness
};

struct RenamedSceneKey {
  std::string_view old_path, new_path;
  KeyConversion conversion = KeyConversion::same;
  std::string_view why;  // for the note
};

struct RetiredSceneKey {
  std::string_view old_path;
  std::string_view instead;  // what the user writes now
};

std::span<const RenamedSceneKey> renamed_scene_keys();
std::span<const RetiredSceneKey> retired_scene_keys();
const RenamedSceneKey* find_renamed_scene_key(std::string_view path);
const RetiredSceneKey* find_retired_scene_key(std::string_view path);

}  // namespace imasim::scene
