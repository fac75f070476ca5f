// The coarse band's further sweeps visit only the rows of particles acted on from outside (the
// tools' contacts, held particles, the fat's columns: physics/active_rows.hpp). Which rows they
// find, and that a chain nothing touches is stepped to the same bits with one coarse sweep as
// with three while a chain pressed by a contact is not.
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "physics/active_rows.hpp"
#include "physics/constraint_system.hpp"
#include "physics/executor.hpp"
#include "physics/state.hpp"
#include "physics/step.hpp"

namespace imasim::physics {
namespace {

constexpr std::uint32_t kChain = 6;  // particles per chain

// Two coarse chains (particles 0-5 and 6-11, each hanging from a fixed first particle) and a
// fine chain (12-17), each particle 10 mm from the next along x.
struct Rig {
  Model model;
  State state;

  Rig() {
    ObjectParams fine, coarse;
    coarse.coarse = true;
    model.objects = {fine, coarse};
    model.solver.substeps = 8;
    model.solver.coarse_stride = 4;
    model.solver.iterations = 1;
    model.solver.coarse_sweeps = 3;
    const MaterialId soft = model.add_material(ConstraintMaterial::xpbd(Real(1e-3)));
    state.constraints.set_object_band(1, true);
    for (int chain = 0; chain < 3; ++chain) {
      const ObjectId object = chain < 2 ? 1 : 0;
      for (std::uint32_t k = 0; k < kChain; ++k) {
        const std::uint32_t i = state.particles.add(
            Vec3(Real(0.01) * Real(k), Real(0.05) * Real(chain), 0), Real(0.001), object);
        if (k == 0) state.particles.fix(i);
        if (k > 0) add_distance(state.constraints, state.particles, i - 1, i, soft, 1);
      }
    }
    prepare_state(model, state);
  }

  // A contact row holding `particle` above the plane y = y0 + 5 mm (it starts below it).
  void press(std::uint32_t particle) {
    ContactRow c;
    c.particle = particle;
    c.normal = Vec3::UnitY();
    c.point0 = c.point1 = state.particles.position[particle] + Vec3(0, Real(0.005), 0);
    state.contacts.rows.push_back(c);
  }
};

// The particles of the rows found, as (i, j) pairs.
std::set<std::pair<std::uint32_t, std::uint32_t>> found_rows(State& state,
                                                             const ActiveRows& active) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> out;
  const auto groups = state.constraints.distance.groups();
  for (std::size_t k = 0; k < active.distance_count; ++k) {
    const DistanceRow& r = groups[active.distance[k].group].rows[active.distance[k].position];
    out.insert({r.i, r.j});
  }
  return out;
}

TEST(ActiveRows, AreTheCoarseRowsOfTheParticlesActedOnFromOutside) {
  Rig rig;
  State& s = rig.state;
  rig.press(14);  // fine: band 0's rows are not the coarse band's
  rig.press(3);
  s.scratch.contact_split = 1;  // band 0 first, as a step orders them
  BodyAttachmentRow held;
  held.particle = 8;
  s.body_attachments = {held};
  s.scratch.body_attachment_split = 0;
  ActiveRows active;
  prepare_active_rows(s, active);
  find_active_rows(s, 1, active);
  const std::set<std::pair<std::uint32_t, std::uint32_t>> expected = {
      {2, 3}, {3, 4}, {7, 8}, {8, 9}};
  EXPECT_EQ(found_rows(s, active), expected);
  EXPECT_EQ(active.attachment_count, 0u);

  // A column on particle 10 (the fat's support rows) is a seed as well; nothing touched, none.
  SupportRow column;
  column.particle = 10;
  s.supports = {column};
  s.scratch.support_split = 0;
  find_active_rows(s, 1, active);
  EXPECT_EQ(found_rows(s, active).count({10, 11}), 1u);
  EXPECT_EQ(found_rows(s, active).count({9, 10}), 1u);
  s.contacts.rows.clear();
  s.body_attachments.clear();
  s.supports.clear();
  s.scratch.contact_split = s.scratch.body_attachment_split = s.scratch.support_split = 0;
  find_active_rows(s, 1, active);
  EXPECT_EQ(active.distance_count, 0u);
}

TEST(ActiveRows, OnlyAChainActedOnFromOutsideIsSweptFurther) {
  // The same steps with one coarse sweep and with three, the first chain's particle 3 held up by
  // a contact: the untouched second chain ends on the same bits, the pressed one does not.
  Rig one, three;
  one.model.solver.coarse_sweeps = 1;
  Executor exec(1);
  for (int n = 0; n < 20; ++n) {
    for (Rig* rig : {&one, &three}) {
      rig->state.contacts.rows.clear();
      rig->press(3);
      ASSERT_TRUE(step(rig->model, rig->state, exec).ok());
    }
  }
  const auto& a = one.state.particles.position;
  const auto& b = three.state.particles.position;
  for (std::uint32_t k = kChain; k < 2 * kChain; ++k)
    EXPECT_EQ(a[k], b[k]) << "untouched chain, particle " << k;
  Real pressed_difference = 0;
  for (std::uint32_t k = 1; k < kChain; ++k)
    pressed_difference = std::max(pressed_difference, (a[k] - b[k]).norm());
  EXPECT_GT(pressed_difference, Real(1e-9));
}

}  // namespace
}  // namespace imasim::physics
