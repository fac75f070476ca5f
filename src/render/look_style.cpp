#include "render/look_style.hpp"

#include "render/renderer.hpp"

namespace imasim::render {

// Colours from intraoperative images of the left hemithorax: pale, glistening fascia over the
// wall; yellow fat; the artery's red; the heart's darker, epicardial-fat-streaked red; white
// bone, bluish cartilage; steel instruments.
LookStyle look_style(Look look) {
  switch (look) {
    case Look::fascia:
      return {{0.86f, 0.70f, 0.66f}, 0.55f, 60.0f};
    case Look::fat:
      return {{0.96f, 0.80f, 0.36f}, 0.45f, 50.0f};
    case Look::ima:
      return {{0.78f, 0.14f, 0.14f}, 0.60f, 70.0f};
    case Look::heart:
      return {{0.62f, 0.20f, 0.20f}, 0.50f, 50.0f};
    case Look::chest_wall:
      return {{0.72f, 0.42f, 0.40f}, 0.35f, 40.0f};
    case Look::bone:
      return {{0.92f, 0.89f, 0.82f}, 0.20f, 20.0f};
    case Look::cartilage:
      return {{0.78f, 0.84f, 0.90f}, 0.40f, 40.0f};
    case Look::instrument:
      return {{0.55f, 0.57f, 0.60f}, 0.90f, 90.0f};
    case Look::electrode:
      return {{0.30f, 0.30f, 0.32f}, 0.90f, 90.0f};
  }
  return {{1, 0, 1}, 0, 1};
}

std::array<std::uint8_t, 3> key_colour(Look look) {
  // Far apart in RGB, so a test can tell them after rasterisation.
  switch (look) {
    case Look::fascia:
      return {255, 255, 255};
    case Look::fat:
      return {255, 255, 0};
    case Look::ima:
      return {255, 0, 0};
    case Look::heart:
      return {0, 0, 255};
    case Look::chest_wall:
      return {0, 255, 0};
    case Look::bone:
      return {255, 0, 255};
    case Look::cartilage:
      return {0, 255, 255};
    case Look::instrument:
      return {128, 128, 128};
    case Look::electrode:
      return {255, 128, 0};
  }
  return {0, 0, 0};
}

}  // namespace imasim::render
