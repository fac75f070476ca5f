#include "surgery/grasp.hpp"

#include <cmath>

namespace imasim::surgery {

Grasper make_grasper(tissue::TissueWorld& world, const GraspParams& params, std::uint32_t body) {
  Grasper g;
  g.body = body;
  if (body == physics::kNoBody)  // with a body the holds carry their compliance themselves
    g.material = world.model.add_material(physics::ConstraintMaterial::xpbd(params.compliance));
  return g;
}

namespace {

void release(tissue::TissueWorld& world, Grasper& g) {
  for (const Grasper::Hold& h : g.held) {
    if (g.body == physics::kNoBody) world.state.constraints.attachment.remove(h.attachment);
    if (h.particle < world.held.size()) world.held[h.particle] = 0;
  }
  g.held.clear();
  g.holding = false;
}

void grasp(tissue::TissueWorld& world, const GraspParams& params, const InstrumentParams& inst,
           const Pose& tool, Grasper& g) {
  physics::Particles& P = world.state.particles;
  const Mat3 to_tool = tool.rotation.transpose();
  auto in_strand = [&](std::uint32_t i) {
    for (const tissue::StrandSet& set : world.strands)
      if (i >= set.first_particle && i < set.first_particle + set.particle_count()) return true;
    return false;
  };
  // The jaws catch the layer they close on: a membrane (fascia, vessel wall) when one lies
  // between them, the fat strands only when none does.
  for (int pass = 0; pass < 2 && g.held.empty(); ++pass) {
    const bool strands = pass == 1;
    for (std::uint32_t i = 0; i < P.size(); ++i) {
      if (P.is_fixed(i) || in_strand(i) != strands) continue;       // fixed: kinematic or removed
      const Vec3 q = to_tool * (P.position[i] - tool.translation);  // (l, n, f) coordinates
      if (q.z() < 0 || q.z() > inst.jaws.length) continue;
      if (std::abs(q.x()) > inst.jaws.width / 2 + params.margin) continue;
      if (std::abs(q.y()) > params.capture_thickness) continue;
      const Vec3 local(q.x(), 0, q.z());  // pinched onto the jaws' plane
      if (i < world.held.size()) world.held[i] = 1;
      Grasper::Hold hold{i, {}, local};
      if (g.body == physics::kNoBody) {
        hold.attachment =
            physics::add_attachment(world.state.constraints, P, i, tool.apply(local), g.material);
      }
      g.held.push_back(hold);
    }
  }
  g.holding = true;
}

}  // namespace

std::uint32_t update_grasp(tissue::TissueWorld& world, const GraspParams& params,
                           const InstrumentParams& inst, const InstrumentState& state, Grasper& g) {
  const Pose tool = world_pose(inst, state);
  if (state.closed && !g.was_closed && !g.holding) grasp(world, params, inst, tool, g);
  if (!state.closed && g.holding) release(world, g);
  g.was_closed = state.closed;
  if (g.body == physics::kNoBody) {
    for (const Grasper::Hold& h : g.held)
      physics::set_attachment_target(world.state.constraints, h.attachment, tool.apply(h.local));
    return static_cast<std::uint32_t>(g.held.size());
  }
  auto& rows = world.state.body_attachments;
  rows.clear();
  for (const Grasper::Hold& h : g.held)
    rows.push_back(
        {h.particle, g.body, tool.apply(h.local), params.compliance, Vec3::Zero(), Vec3::Zero()});
  return static_cast<std::uint32_t>(g.held.size());
}

Vec3 grasp_force_on_jaws(const physics::Particles& particles, const GraspParams& params,
                         const Pose& jaws, const Grasper& grasper) {
  if (!(params.compliance > 0)) return Vec3::Zero();  // rigid holds carry no measurable force
  Vec3 stretch = Vec3::Zero();
  for (const Grasper::Hold& h : grasper.held)
    if (h.particle < particles.size())
      stretch += particles.position[h.particle] - jaws.apply(h.local);
  return stretch / params.compliance;
}

}  // namespace imasim::surgery
