#pragma once
// An implicit step for a small membrane (the fascia: about 500 vertices) whose edges are
// strain-stiffening springs (stiffening_spring.hpp). One backward-Euler step minimises the
// incremental potential
//   Phi(x) = 1/(2 h^2) |x - y|_M^2 + sum_e E_e(|x_i - x_j|) + sum_k E_k(x) + sum_c E_c(x)
//            + sum_c D_c(x) - f . x,
// y = x0 + h v0 + h^2 g, E_k the hinges' bending (MembraneHinge), E_c the penalties of the
// contacts on tools' bodies (MembraneContact; fixed planes hold their vertices exactly instead),
// D_c the contacts' friction (friction_potential),
// by Newton's method: the Hessian (M / h^2 plus, per edge, the regime's stiffness along the edge
// and the tension's T / l across it) is factored by sparse Cholesky of 3 x 3 blocks
// (block_cholesky.hpp; the pattern analysed once at set-up), and each iteration backtracks along
// its step until Phi falls. The factorisation, the costly part, is kept across iterations and steps
// while it converges fast (modified Newton). Stiffness costs no substeps and no sweeps: a stiff
// edge is stiff in the matrix, which the factorisation inverts exactly.
//
// Why not projective dynamics (a constant matrix factored once): its matrix gives every edge its
// axial stiffness in all three directions. A taut membrane pushed across its plane resists with
// its tension T / l, four orders below the axial stiffness of the fascia's linear region, so the
// local/global rounds crawl: 8 rounds a 5 ms step left 0.13 N of a 0.3 N press unbalanced and
// the press 28 % short (docs/physics.md).
//
// Across an edge in compression the tension term is negative: the Hessian keeps it while the
// matrix stays positive definite (the mass and the bending hold a slack membrane), and drops it
// when that factorisation fails, so the matrix factored is positive definite always;
// the line search keeps the step a descent on the true potential. A cut zeroes an edge and keeps
// the pattern. Fixed vertices are moved by the caller and enter as known.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "math/types.hpp"
#include "physics/block_cholesky.hpp"
#include "physics/executor.hpp"
#include "physics/stiffening_spring.hpp"

namespace imasim::physics {

struct MembraneEdge {
  std::uint32_t i = 0, j = 0;
  StiffeningSpring spring;
};

// Bending across an interior edge (v[0], v[1]) between the wings v[2] and v[3], for a membrane
// flat at rest: E = k / 2 |sum_i w_i x_i|^2. The weights vanish on every affine image of the rest
// hinge (sum w_i = 0, sum w_i x_i = 0 at rest) and give sum w_i x_i = theta n for a wing turned
// by a small dihedral angle theta, so E is the XPBD dihedral row's k theta^2 / 2 for small
// bending; its Hessian, k w_i w_j I, is constant (Bergou et al. 2006's quadratic bending).
struct MembraneHinge {
  std::array<std::uint32_t, 4> v{};
  std::array<Real, 4> w{};  // (unit: 1/m)
  Real stiffness = 0;       // k = D |e|^2 / (A_1 + A_2) (unit: N m)
};

// Bending across an interior edge (v[2], v[3]) between the wings v[0] and v[1], for a surface
// curved at rest (a tube's wall): E = k / 2 (theta - theta_0)^2, theta the signed dihedral angle of
// eq. 3 (physics/dihedral_constraint.hpp: the XPBD dihedral row's C, the same energy that row's
// compliance 1 / k gives). Rotating the hinge leaves theta as it is, so a curved surface carried
// round rigidly feels nothing, which MembraneHinge's constant curvature vector cannot give when it
// is not zero at rest. Its Hessian is taken as Gauss-Newton's, k grad theta grad theta^T: positive
// semi-definite, exact at the rest angle, and the line search keeps each step a descent.
struct MembraneDihedral {
  std::array<std::uint32_t, 4> v{};  // wing0, wing1, edge start, edge end (DihedralRow's order)
  Real rest_angle = 0;               // theta_0 (unit: rad)
  Real stiffness = 0;                // k (unit: N m)
};

inline constexpr std::uint32_t kNoMembraneBody = 0xffffffffu;

// A rigid body solved with the membrane: a tool's proxy, held to its device by a spring and a
// damper (eq. 17's coupling) and pushed by the membrane through the contacts that name it. Its
// energy over the step, k/2 |o - anchor|^2 + c / (2 h) |o - o_start|^2, is backward Euler's for a
// massless body on that spring and damper.
struct MembraneBody {
  Vec3 anchor = Vec3::Zero();    // where the spring pulls it: the device (unit: m)
  Real stiffness = 0;            // k (unit: N/m)
  Real damping = 0;              // c (unit: N s/m); k or c positive
  Vec3 position = Vec3::Zero();  // o: its place at the step's start, and at its end (unit: m)
};

// A vertex kept on the positive side of a plane (a rigid surface or a tool, linearised for the
// step: the caller places the plane where the surface will be at the step's end).
// - A plane on a body (a tool's proxy) moves with it, gap = n . (x - p - (o - o_start)), and
//   pushes by a stiff one-sided spring, energy k/2 min(0, gap)^2: a penalty the Newton solve
//   sees whole.
// - A fixed plane (no body) holds exactly: a vertex that reaches it (at the step's first iterate,
//   or when a Newton step would carry it through) is put on it and kept there, sliding freely
//   along it, until the plane would have to pull it back; then it is let go for the rest of the
//   step, the penalty its only guard (an active set). Why not the penalty: a membrane resting on
//   a moving surface (the fascia on the beating heart) reaches the planes one by one, and the
//   Newton solve, whose line search stops at the first vertex to cross, took 15-20 iterations a
//   step; holding every crossing vertex at once takes 2-3.
// - Friction, on either kind: smoothed Coulomb friction against the vertex's slip over the step
//   relative to the surface (friction_potential below), pressed with the normal force of the
//   caller's last step (lagged: the normal force is known only once a step is solved).
struct MembraneContact {
  std::uint32_t vertex = 0;
  Vec3 point = Vec3::Zero();    // on the plane (unit: m)
  Vec3 normal = Vec3::UnitY();  // unit, out of the surface
  std::uint32_t body = kNoMembraneBody;
  Vec3 motion = Vec3::Zero();  // the surface's own motion over the step at the point (unit: m)
  Real friction = 0;           // mu (unit: 1)
  Real normal_force = 0;       // lambda, from the last step; no friction while 0 (unit: N)
};

// Smoothed Coulomb friction over one step (the lagged, smoothed friction of Li et al. 2020, IPC):
// a contact pressing with normal force lambda resists its vertex's tangential slip u over the step
// (relative to the surface) with the potential mu lambda f0(|u|), where f0(s) = s at and past the
// stick-slip distance eps and -s^3 / (3 eps^2) + s^2 / eps + eps / 3 below it. Its force,
// mu lambda f0'(|u|) against u, is Coulomb's whole mu lambda once the slip reaches eps and a stiff
// spring (2 mu lambda / eps at rest) below it: a vertex under a tangential load F < mu lambda
// creeps by eps (1 - sqrt(1 - F / (mu lambda))) a step instead of sticking exactly. Every term of
// its Hessian is positive semi-definite, so Newton takes it whole.
struct FrictionTerms {
  Real energy = 0;      // mu lambda f0(s) (unit: J)
  Real per_slip = 0;    // mu lambda f0'(s) / s: the force is -per_slip u (unit: N/m)
  Real along_slip = 0;  // mu lambda f0''(s): the stiffness along u (unit: N/m)
};
FrictionTerms friction_potential(Real mu_lambda, Real slip, Real stick_slip);

// The normal force the contact's surface exerts on its vertex at x (unit: N); moved: how far the
// contact's body moved in the step (o - o_start), zero for a fixed surface.
inline Real contact_force(const MembraneContact& c, const Vec3& x, Real stiffness,
                          const Vec3& moved = Vec3::Zero()) {
  const Real gap = c.normal.dot(x - c.point - moved);
  return gap < 0 ? -stiffness * gap : Real(0);
}

// A vertex held by a tool (the forceps' grasp): a stiff spring to a target that rides on the
// tool's body, energy k/2 |x - t - (o - o_start)|^2, or a fixed target without a body. The
// body attachment of physics/body_attachment.hpp (compliance 1 / k), solved with the membrane.
struct MembraneAttachment {
  std::uint32_t vertex = 0;
  Vec3 target = Vec3::Zero();  // where the body's start puts it (unit: m)
  std::uint32_t body = kNoMembraneBody;
  Real stiffness = 0;  // k (unit: N/m)
};

// The force an attachment's spring pulls its body with, toward the vertex at x (unit: N); moved:
// how far the body moved in the step (o - o_start).
inline Vec3 attachment_pull(const MembraneAttachment& a, const Vec3& x,
                            const Vec3& moved = Vec3::Zero()) {
  return a.stiffness * (x - a.target - moved);
}

// A body stopped by a fixed surface (a tool's proxy at the heart or the chest wall: the body stop
// of physics/body_stop.hpp): a point of the body kept on the plane's outer side, gap = gap0 +
// n . (o - o_start), by a stiff one-sided spring, energy k/2 min(0, gap)^2. Without it the
// membrane's step would carry a pressed tool into the surface, and the tissue it holds with it.
struct MembraneBodyStop {
  std::uint32_t body = 0;
  Vec3 normal = Vec3::UnitY();  // unit, out of the surface
  Real gap0 = 0;                // the gap with the body where the step starts (unit: m)
};

// A column holding a vertex to a fixed base (the fat under the fascia, physics/support_row.hpp):
// energy k/2 g^2, g = n . (x - point), or k/2 min(g, 0)^2 if it pushes only.
struct MembraneSupport {
  std::uint32_t vertex = 0;
  Vec3 point = Vec3::Zero();    // on the column's plane at rest (unit: m)
  Vec3 normal = Vec3::UnitY();  // unit, away from the base
  Real stiffness = 0;           // k (unit: N/m)
  bool pushes_only = true;
};

// What acts on the membrane during one step besides its springs.
struct ImplicitLoads {
  Vec3 gravity = Vec3::Zero();                // (unit: m/s^2)
  std::span<const Vec3> force;                // per vertex (unit: N), or empty
  std::span<const MembraneContact> contacts;  // any number, a vertex in several
  std::span<MembraneBody> bodies;             // as many as the solver was made for
  std::span<const MembraneAttachment> attachments = {};
  std::span<const MembraneBodyStop> body_stops = {};
  std::span<const MembraneSupport> supports = {};
};

struct ImplicitSolveParams {
  // Newton iterations a step at most: 1-2 in a tool's steady press, 15 in the first step of a
  // flat membrane loaded across its plane, which resists by its mass alone until it sags, 20-40
  // in the rare step where many held vertices change between sticking and sliding (friction).
  std::uint32_t max_iterations = 40;
  // Stop when no free vertex's force imbalance exceeds this (unit: N).
  Real tolerance = Real(1e-6);
  // The factorisation is kept across iterations and steps while each iteration leaves at most
  // this share of the imbalance before it, and refactored at the iterate when one does not.
  Real kept_matrix_ratio = Real(0.25);
  // The contacts' penalty (unit: N/m): a vertex pressed with 0.1 N stays 1 um inside.
  Real contact_stiffness = Real(1e5);
  // The body stops' penalty (unit: N/m): a tool pressed on the chest wall with 3 N stays 0.3 um
  // inside, which the XPBD step's hard stop takes out without moving the tissue the tool holds.
  Real body_stop_stiffness = Real(1e7);
  // A vertex the step's first iterate finds within this of a fixed plane starts on it, held: the
  // membrane that rested on the plane at the last step's end (unit: m).
  Real hold_distance = Real(1e-6);
  // false: a fixed plane is a penalty too, as a body's is (the comparison in the tests).
  bool hold_fixed_planes = true;
  // Friction's stick-slip distance eps (friction_potential): the slip over a step below which a
  // contact's friction is a spring rather than Coulomb's mu lambda; a stuck vertex under half its
  // bound creeps 0.29 eps a step (unit: m).
  Real stick_slip = Real(1e-6);
};

struct ImplicitStepReport {
  std::uint32_t iterations = 0;      // Newton iterations taken
  std::uint32_t factorizations = 0;  // of the Hessian, a failed exact one counted
  // Of those, the ones made because the vertices held on fixed planes were not the kept
  // factorisation's (or none was kept); the rest because the kept one converged too slowly or
  // found no descent.
  std::uint32_t active_set_factorizations = 0;
  // Newton iterations whose line search took less than the full step (a vertex reaching a
  // plane, a penalty's kink, the potential rising).
  std::uint32_t shortened_iterations = 0;
  // Largest force imbalance of the step at a free vertex at its end,
  // |m (x - y) / h^2 + grad E - f| (unit: N): zero when the step is solved exactly.
  Real residual = 0;
  bool ok = true;  // false: a factorisation failed
};

class ImplicitMembrane {
 public:
  // mass (unit: kg) and fixed (1: moved by the caller) per vertex; h the step (unit: s).
  // Throws std::invalid_argument naming what is wrong (sizes, a free vertex without mass, an
  // edge out of range, a stiffness or h not positive, a linear stiffness below the toe's).
  // bodies: how many MembraneBody the loads of every step bring (each solved with the membrane).
  // dihedrals: bending of a surface curved at rest, beside or instead of the flat hinges.
  ImplicitMembrane(std::vector<Real> mass, const std::vector<std::uint8_t>& fixed,
                   std::vector<MembraneEdge> edges, Real h, std::vector<MembraneHinge> hinges = {},
                   std::uint32_t bodies = 0, std::vector<MembraneDihedral> dihedrals = {});

  // One step of length h. x, v: every vertex (unit: m, m/s); the fixed ones' x are their
  // positions at the step's end and are left as they are, as are their v. Throws
  // std::invalid_argument for what it was not made for (x, v or a force not one per vertex,
  // the bodies' count, a contact or an attachment naming a vertex or body out of range, an
  // attachment's stiffness not positive, a body with neither stiffness nor damping). The report's
  // residual says how far the step was solved: above the tolerance when max_iterations ran out.
  ImplicitStepReport step(std::span<Vec3> x, std::span<Vec3> v, const ImplicitLoads& loads,
                          const ImplicitSolveParams& params);
  // The same step with the elements' forces evaluated on exec's threads: the same result for any
  // thread count.
  ImplicitStepReport step(std::span<Vec3> x, std::span<Vec3> v, const ImplicitLoads& loads,
                          const ImplicitSolveParams& params, const Executor& exec);

  // The normal force each contact of the last step's loads exerted at its end, in their order
  // (unit: N): a held vertex's the plane's reaction (the force its other loads press it with), a
  // penalty's k |gap|.
  std::span<const Real> contact_forces() const { return contact_forces_; }
  // The friction each contact exerted on its vertex at the step's end, in the same order (unit:
  // N): along its plane; the contact's body, if it has one, took the opposite.
  std::span<const Vec3> contact_frictions() const { return contact_frictions_; }

  // A cut: edge e pulls no more; hinge k bends no more.
  void remove_edge(std::size_t e);
  void remove_hinge(std::size_t k);
  void remove_dihedral(std::size_t k);
  // Coagulation: edge e's toe and linear stiffness times `factor` (> 0).
  void scale_edge(std::size_t e, Real factor);
  std::span<const MembraneEdge> edges() const { return edges_; }

  std::size_t free_count() const { return free_vertices_.size(); }

 private:
  static constexpr std::uint32_t kFixed = 0xffffffffu;
  using Dense = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  // A 3 x 3 block of the Hessian: its index in hessian_ (the diagonal blocks first, then one per
  // pair of block rows, a block and its transpose being one), or kFixed where an end is fixed.
  // Every block added is symmetric, so a pair's orientation does not matter.
  using Block = std::uint32_t;
  struct EdgeBlocks {
    Block ii = kFixed, jj = kFixed, ij = kFixed;
  };

  // Phi at x (bx: the bodies' positions), and its gradient over the free rows and the bodies'
  // into `gradient`: the elements' terms on exec's threads (evaluate_elements), then gathered.
  Real evaluate(std::span<const Vec3> x, std::span<const Vec3> bx, const ImplicitLoads& loads,
                Real contact_k, Dense& gradient, const Executor& exec);
  // implicit_membrane_elements.cpp: which elements reach each free row (set-up), each element's
  // terms at x, and a row's elastic gradient gathered from them in element order.
  void index_elements();
  void evaluate_elements(std::span<const Vec3> x, const Executor& exec);
  Vec3 gather_elements(std::uint32_t row, Vec3 g) const;
  Real add_elements_energy(Real phi) const;  // phi plus theirs, in element order
  // exact: compressed edges' negative tension term kept (may fail: not positive definite).
  bool factor_hessian(std::span<const Vec3> x, std::span<const Vec3> bx, const ImplicitLoads& loads,
                      Real contact_k, bool exact);
  Real body_stop_gap(const MembraneBodyStop& r, std::span<const Vec3> bx) const;
  // A contact's gap at x (with its body at bx), and its body's row or kFixed.
  Real gap(const MembraneContact& c, std::span<const Vec3> x, std::span<const Vec3> bx) const;
  // A contact's tangential slip over the step relative to its surface (and its body) at x.
  Vec3 slip(const MembraneContact& c, std::span<const Vec3> x, std::span<const Vec3> bx) const;
  // Whether a contact's friction acts in this step: mu and lambda given, its vertex free.
  bool rubs(const MembraneContact& c) const;
  // The held rows' normal taken out of the matrix (S H S + (m / h^2) n n^T, S = I - n n^T), so
  // that a solve moves them along their planes only.
  void filter_held(const ImplicitLoads& loads);
  // The rows' imbalance as convergence reads it: a held row's along its plane, and its normal
  // part too when the plane would have to pull.
  Real largest_imbalance(const ImplicitLoads& loads) const;
  // Vertices a trial carried through a fixed plane put on it, to be held from that iterate on.
  void project_crossing(const ImplicitLoads& loads, std::span<const Vec3> x);

  std::vector<Real> mass_;
  std::vector<MembraneEdge> edges_;
  std::vector<std::uint8_t> removed_;
  Real h_ = 0;
  static constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<std::uint32_t> free_index_;     // per vertex: its block row, or kFixed
  std::vector<std::uint32_t> free_vertices_;  // per block row: its vertex
  std::vector<Block> diagonal_;               // per block row
  std::vector<EdgeBlocks> blocks_;
  std::vector<MembraneHinge> hinges_;
  std::uint32_t body_count_ = 0;
  Real body_stop_k_ = 0;  // this step's ImplicitSolveParams::body_stop_stiffness (unit: N/m)
  Real stick_slip_ = 0;   // this step's ImplicitSolveParams::stick_slip (unit: m)
  // Per body: its diagonal block, and its block with every free vertex: a contact may join it to
  // any.
  std::vector<Block> body_diagonal_;
  std::vector<std::vector<Block>> body_vertex_;
  std::vector<Vec3> body_start_, body_target_, body_x_, body_trial_;
  std::vector<Real> body_weight_;  // (c / h + k) of each body (unit: N/m)
  std::vector<std::uint8_t> hinge_removed_;
  std::vector<std::array<Block, 16>> hinge_blocks_;  // (a, b) at 4 a + b
  std::vector<MembraneDihedral> dihedrals_;
  std::vector<std::array<Real, 2>> dihedral_rest_;  // cos, sin of each one's rest angle
  std::vector<std::uint8_t> dihedral_removed_;
  std::vector<std::array<Block, 16>> dihedral_blocks_;  // as hinge_blocks_
  std::vector<BlockCholesky::Pair> pairs_;  // the off-diagonal blocks' rows, as analysed
  // The active set, per free row: the contact holding it (kNone: none), the one a trial put it on,
  // whether it was let go this step, and the rows the kept factorisation held.
  std::vector<std::uint32_t> held_, pending_;
  std::vector<std::uint8_t> released_, factored_held_;
  std::vector<Real> contact_forces_;
  std::vector<Vec3> contact_frictions_;
  std::vector<Mat3> hessian_;  // its blocks, as Block indexes them
  // Its part no iterate changes (masses, hinges), rebuilt after a hinge is cut.
  std::vector<Mat3> constant_hessian_;
  bool constant_stale_ = true;
  std::uint32_t block_rows_ = 0;
  BlockCholesky cholesky_;
  bool factored_ = false;  // cholesky_ holds a factorisation to keep
  std::vector<Vec3> x0_, y_, trial_;
  Dense gradient_, trial_gradient_, direction_;
  // The elements' terms at the iterate evaluate() last read, each computed apart (in parallel)
  // and gathered per free row in element order: the sums a serial scatter would make.
  std::vector<std::uint8_t> edge_terms_;      // 0: none (cut), 1: energy only (no length), 2: both
  std::vector<Real> edge_energy_;             // (unit: J)
  std::vector<Vec3> edge_gradient_;           // dE/dx_i, x_j's the opposite (unit: N)
  std::vector<Vec3> hinge_curvature_;         // sum_i w_i x_i (unit: 1)
  std::vector<std::uint8_t> dihedral_terms_;  // 0: cut or degenerate
  std::vector<Real> dihedral_value_;          // theta - theta_0 (unit: rad)
  std::vector<std::array<Vec3, 4>> dihedral_grad_;  // d theta / d x_p (unit: 1/m)
  // Per free row, the elements that reach it: edge 2 e (+1: as its x_j), hinge or dihedral
  // 4 k + p (its vertex p), ascending; *_start_ has a row's first entry.
  std::vector<std::uint32_t> row_edges_start_, row_edges_;
  std::vector<std::uint32_t> row_hinges_start_, row_hinges_;
  std::vector<std::uint32_t> row_dihedrals_start_, row_dihedrals_;
};

}  // namespace imasim::physics
