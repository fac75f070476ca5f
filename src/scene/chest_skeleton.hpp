#pragma once
// The bony frame of the anterior chest wall, for display only (nothing collides with it): the
// sternum, the costal cartilages from its edge and the ribs beyond them, all just outside the
// wall's inner surface, the IMA running behind the cartilages (SPEC S3, paper 2.1).
#include <string>
#include <vector>

#include "geometry/triangle_mesh.hpp"
#include "scene/anatomy.hpp"

namespace imasim::scene {

enum class BoneKind { sternum, costal_cartilage, rib };

struct DisplayMesh {
  std::string name;  // "sternum", "costal_cartilage_3", "rib_3"
  BoneKind kind = BoneKind::sternum;
  geometry::TriangleMesh mesh;  // (unit: m), outward normals
};

struct ChestSkeletonParams {
  Real gap = Real(0.002);  // between the wall's inner surface and the bone (unit: m)
  Real sternum_thickness = Real(0.012);
  Real rib_radius = Real(0.005);        // of the round rib and cartilage cross-section (unit: m)
  Real cartilage_length = Real(0.02);   // lateral reach of the first cartilage past the sternum
  Real cartilage_growth = Real(0.005);  // each lower cartilage reaches this much further (m)
  Real lateral_extent = Real(0.12);     // ribs end this far from the midline (unit: m)
};

// One sternum, then for each rib level (every rib_spacing along the IMA's course, from its
// cranial end) a costal cartilage and a rib.
std::vector<DisplayMesh> make_chest_skeleton(const AnatomyParams& anatomy,
                                             const ChestSkeletonParams& params = {});

}  // namespace imasim::scene
