// Tissue the forceps hold is left out of the rigid surfaces' rows (tissue/surface_contacts.hpp):
// it goes where the jaws take it. A held particle pushed out by the heart while the grasp pulls it
// in would be two rigid rows fighting (GraspPull.* in the physics checks shows what that did).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tissue/surface_contacts.hpp"

namespace imasim::tissue {
namespace {

physics::ContactSet rows_of(const std::vector<std::uint32_t>& particles) {
  physics::ContactSet set;
  for (std::uint32_t i : particles) {
    physics::ContactRow r;
    r.particle = i;
    r.tag = 100 + i;
    set.rows.push_back(r);
  }
  return set;
}

TEST(HeldRows, RowsOfHeldParticlesGoAndTheOthersKeepTheirOrder) {
  physics::ContactSet set = rows_of({0, 3, 1, 3, 2, 7});
  const std::vector<std::uint8_t> held = {0, 1, 0, 1};  // 1 and 3 held; 7 past the flags
  const std::size_t capacity = set.rows.capacity();
  drop_held_rows(set, 0, held);
  ASSERT_EQ(set.rows.size(), 3u);
  EXPECT_EQ(set.rows[0].particle, 0u);
  EXPECT_EQ(set.rows[1].particle, 2u);
  EXPECT_EQ(set.rows[2].particle, 7u);
  EXPECT_EQ(set.rows[2].tag, 107u);  // the whole row moved, not only its particle
  EXPECT_EQ(set.rows.capacity(), capacity);
}

TEST(HeldRows, RowsBeforeTheFirstAreKeptAndNoFlagsDropNothing) {
  physics::ContactSet set = rows_of({1, 1, 1});
  drop_held_rows(set, 1, std::vector<std::uint8_t>{0, 1});
  ASSERT_EQ(set.rows.size(), 1u);  // the first row was not looked at
  EXPECT_EQ(set.rows[0].tag, 101u);
  physics::ContactSet all = rows_of({0, 1, 2});
  drop_held_rows(all, 0, {});
  EXPECT_EQ(all.rows.size(), 3u);
}

// In the scene: the floor's rows for a particle come and go with its flag.
TEST(HeldRows, TheFloorPushesAParticleUnlessItIsHeld) {
  physics::Particles P;
  P.add(Vec3(0, Real(0.0001), 0), Real(0.001), 0);  // just above the floor
  P.add(Vec3(0, Real(0.0001), Real(0.01)), Real(0.001), 0);
  physics::ContactSet set;
  gather_floor_contacts(0, P, Real(0.005), SurfaceContactParams{}, set);
  ASSERT_EQ(set.rows.size(), 2u);
  drop_held_rows(set, 0, std::vector<std::uint8_t>{0, 1});
  ASSERT_EQ(set.rows.size(), 1u);
  EXPECT_EQ(set.rows[0].particle, 0u);
}

}  // namespace
}  // namespace imasim::tissue
