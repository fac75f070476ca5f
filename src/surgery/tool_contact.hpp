#pragma once
// Instrument-tissue contact (SPEC S4): the instrument's geometry (a capsule for the shaft, an
// oriented box per jaw) pushes dynamic tissue particles out of it. Each penetration is an XPBD
// positional contact constraint against a kinematic (infinitely heavy) tool, with Coulomb
// friction in positional form (Mueller et al. 2020, "Detailed rigid body simulation with
// extended position based dynamics"): static friction holds the particle to the tool while its
// tangential slip this step is below mu_s times the normal correction; otherwise the slip is
// reduced by mu_k times the normal correction.
//
// In the session the instruments' contacts are constraints inside the solve: gather_tool_contacts
// hands the solver, before each step, the tangent plane of each shape near each particle
// (physics/contact.hpp); summarize_tool_contacts reads back what touched. resolve_tool_contacts,
// after the step, puts out what the gathering missed (a warning count) and serves the tests of
// the shapes: it sets the velocity of every particle it moves to (x_new - x_start) / dt, so
// position and velocity agree.
#include <cstdint>
#include <span>
#include <vector>

#include "math/pose.hpp"
#include "physics/contact.hpp"
#include "physics/particles.hpp"
#include "surgery/instrument.hpp"

namespace imasim::surgery {

// The points within `radius` of the segment [a, b].
struct Capsule {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();  // (unit: m)
  Real radius = 0;                          // (unit: m)
};

// The box |R^T (x - c)|_i <= half_extents_i with c = pose.translation, R = pose.rotation (its
// columns are the box's axes).
struct OrientedBox {
  Pose pose;
  Vec3 half_extents = Vec3::Zero();  // (unit: m)
};

struct ToolGeometry {
  std::vector<Capsule> capsules;
  std::vector<OrientedBox> boxes;
  Vec3 velocity = Vec3::Zero();  // the tool's linear velocity this step (unit: m/s)
};

// Every shape moved by `by` (unit: m): the tool carried by its proxy's offset within a step.
void translate_tool_geometry(ToolGeometry& tool, const Vec3& by);

// Thickness of a jaw's box along its opening direction n (unit: m).
inline constexpr Real kJawThickness = Real(1e-3);

// The instrument's geometry in the world: capsules[0] is the shaft (radius shaft_radius, from
// the hinge back along -f for shaft_length); boxes[0] and boxes[1] are the upper and lower jaws
// (from the hinge to the jaw's tip along its f, width along l, kJawThickness along n, centred
// half-way; axes the jaw pose's columns). Sets velocity to zero: the caller knows the tool's
// motion. No allocation when `out` already holds the capacity (one capsule, two boxes).
void make_tool_geometry(const InstrumentParams& params, const InstrumentState& state,
                        ToolGeometry& out);

// The closest point on a shape's surface to x.
struct SurfacePoint {
  Real distance = 0;           // signed distance of x, negative inside (unit: m)
  Vec3 point = Vec3::Zero();   // closest surface point (unit: m)
  Vec3 normal = Vec3::Zero();  // outward unit normal there; x = point + distance * normal
};

// On the axis (where the direction is undefined) the normal is a fixed direction perpendicular
// to the axis.
SurfacePoint capsule_surface(const Capsule& capsule, const Vec3& x);
// Inside: the nearest face (ties go to the lowest axis, then the + face). Outside: the closest
// point and normal (x - point) / |x - point|.
SurfacePoint box_surface(const OrientedBox& box, const Vec3& x);

struct ContactParams {
  Real compliance = 0;  // alpha (unit: m/N); 0 = hard contact
  // mu_s, mu_k of the gathered rows. prepare_proxy_body replaces them with the touched tissue's
  // eq. 18 mu (ProxyParams::friction); these stay for a particle of no tissue and for the
  // after-step pass of resolve_tool_contacts.
  Real static_friction = Real(0.6);
  Real kinetic_friction = Real(0.4);
  Real margin = Real(0.2e-3);  // kept between tool and tissue (unit: m)
};

struct ToolContact {
  std::uint32_t particle = 0;
  Vec3 point = Vec3::Zero();   // on the tool's surface, before the projection (unit: m)
  Vec3 normal = Vec3::Zero();  // the tool's outward normal there
  Real depth = 0;              // penetration including the margin, > 0 (unit: m)
};

struct ContactSummary {
  std::uint32_t count = 0;  // contacts (a particle counts once per shape it penetrates)
  std::uint32_t inside =
      0;               // of which the particle was inside the shape itself, not only the margin
  Real max_depth = 0;  // (unit: m)
  Vec3 point = Vec3::Zero(), normal = Vec3::Zero();  // of the deepest contact (the first one)
  std::uint32_t per_object[8] = {};  // contacts by ObjectId (ids >= 8 counted in slot 7)
};

// Resolves the contacts of every dynamic particle (inverse_mass > 0) with the tool; `start`
// holds the positions at the step's start (at least particles.size() of them), dt > 0 is the
// step (unit: s). Contacts are appended to `contacts` after clearing it (reserve its capacity at
// set-up: nothing is allocated while it fits). Deterministic: particles in index order, each
// projected, in one pass, against every shape it penetrates, in order (capsules, then boxes).
//
// Per contact with penetration d = margin - signed distance > 0, inverse mass w and
// alpha~ = compliance / dt^2: dlambda = d / (w + alpha~), x += w dlambda n (compliance 0 puts x
// on the surface plus the margin). Friction, with the normal correction dn = w dlambda (= d when
// hard) and the slip relative to the tool dp_t, the tangential part of
// (x - start) - velocity dt: |dp_t| < mu_s dn sticks (x -= dp_t), else
// x -= dp_t min(mu_k dn / |dp_t|, 1).
ContactSummary resolve_tool_contacts(physics::Particles& particles, std::span<const Vec3> start,
                                     const ToolGeometry& tool, const ContactParams& params, Real dt,
                                     std::vector<ToolContact>& contacts);

}  // namespace imasim::surgery

namespace imasim::surgery {

// Appends the tool's contacts for the coming step: for each dynamic particle whose predicted
// position x + v dt comes within `search` (plus the margin and its motion) of a shape, that
// shape's tangent plane at the nearest point on the tool at the step's end (`tool`, pose `now`),
// and the same point of the tool at the step's start, carried back by the tool's rigid motion
// (`before` -> `now`), so each contact point moves with the tool's own velocity there (a shaft
// pivoting about its port moves fastest at its tip). Rows carry `tag`.
void gather_tool_contacts(const physics::Particles& particles, const ToolGeometry& tool,
                          const Pose& before, const Pose& now, const ContactParams& params, Real dt,
                          std::uint32_t tag, physics::ContactSet& out, Real search = Real(0.002));

// After the step: the rows with `tag` that touched in the step's last substep (count, deepest,
// contacts by object).
ContactSummary summarize_tool_contacts(const physics::Particles& particles,
                                       const physics::ContactSet& contacts, std::uint32_t tag);

}  // namespace imasim::surgery
