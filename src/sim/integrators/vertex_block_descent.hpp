// Vertex block descent on the implicit BDF2 step: every force implicit, solved vertex by vertex.
#pragma once

#include <optional>
#include <vector>

#include "sim/contact/smooth_collider.hpp"
#include "sim/contact/smooth_contact.hpp"
#include "sim/integrators/affine_correction.hpp"
#include "sim/integrators/coarse_space.hpp"
#include "sim/integrators/integrators.hpp"
#include "sim/integrators/joint_affine_correction.hpp"
#include "sim/integrators/lane_groups.hpp"
#include "sim/integrators/vertex_blocks.hpp"
#include "sim/integrators/vertex_contacts.hpp"
#include "sim/integrators/vertex_energy.hpp"
#include "sim/integrators/vertex_moves.hpp"

namespace sim {

// The level of vbd's steps (dt / 2^level) through an impact on a smooth contact of ω [1/s] within a driver's step dt:
// the shallowest with ω h ≤ `impact_phase` (solver.impact_phase), at most its deepest level.
int vbd_impact_level(double dt, double omega, double impact_phase);

// Each step of h is one implicit step of the model's ODE (Chen, Liu, Yang & Yuksel, "Vertex Block Descent",
// SIGGRAPH 2024, for the solve; Ascher & Petzold, "Computer Methods for ODEs and DAEs", Sect. 5.1, for BDF2):
//   BDF2      x' − x̃ = ĥ v',  v' − ṽ = ĥ f(x', v')/m,  ĥ = 2h/3, x̃ = (4x_n − x_{n−1})/3, ṽ = (4v_n − v_{n−1})/3
//             (at a constant h; with a step ratio ω = h_n/h_{n−1} ≤ 2 its variable-step form, set_targets)
//   backward Euler (a run's first step, after a contact moved the state, after h grew over 2×): ĥ = h, x̃ = x_n
// One call of step(dt) takes one such step, or several around an impact on a smooth contact (next_level).
// Eliminating v' leaves m (x' − y)/ĥ² = f(x', (x' − x̃)/ĥ), y = x̃ + ĥ ṽ + ĥ² g, the stationary point of
//   E(x) = Σ_i m_i |x_i − y_i|² / (2ĥ²) + Σ_e ½ k (|d_e| − L0)² − nRT ln V + D(x) + floor terms        [J]
// with the dampers' and the smooth floor's dissipation D taken with their directions and weights lagged at the
// current iterate (so that the fixed point is the scheme's, exactly; Li et al. 2020 lag friction the same way).
// Gauss–Seidel over the vertices (solver.iterations sweeps, or with "converge" or "auto" until a sweep barely moves a
// vertex;
// colour by colour, sim/integrators/vertex_blocks.hpp):
// vertex i moves by one Newton step on E as a function of x_i alone, H_i Δ = −∇_i E, with the 3×3 block
//   H_i = m/ĥ² I + Σ_e [k (n̂n̂ᵀ + max(0, 1 − L0/l)(I − n̂n̂ᵀ)) + (c/ĥ) n̂n̂ᵀ] + nRT g_i g_iᵀ / V² + floor terms,
// g_i = ∂V/∂x_i = Σ_{f ∋ i} (x_b − x_i) × (x_c − x_i) / 6. V is affine in x_i, so the gas term is its exact local
// Hessian; a compressed spring's negative transverse curvature is clamped at zero, so H_i is positive definite and Δ a
// descent direction. A backtracking line search on E's change (Armijo, α = 1, ½, ...) accepts only a move that lowers
// E. A colour's vertices move at once (on solver.threads), each from V at the colour's start, and V is updated
// exactly after the colour (V += Σ g_i·Δ_i); only the gas couples them, and a bound on that coupling refuses a joint
// move that might raise E (vertex_moves.hpp): the colour is then visited a vertex at a time, V updated after each
// move. So no setting can make a sweep add energy, whatever h. Then v' = (x' − x̃)/ĥ.
// Before each sweep, a correction on a coarse space carries what a sweep, which moves information by one ring of
// vertices, cannot: where `aggregates` is set (solver.coarse_space), one Newton step on smooth fields over that many
// cells and the body's linear motions (coarse_space.hpp; before every other sweep, its matrix assembled and factored
// every few steps and reused between), else one restricted to the body's affine motions (affine_correction.hpp). Both
// search E along their step. At an impact's steps, where the sweeps go on until still, only the first few sweeps take
// them (kImpactCorrectedSweeps).
// The smooth floor, the smooth colliders and the smooth contact between bodies (self-contact included) enter E with
// their dashpot weights and friction normal forces lagged (vertex_energy.hpp, sim/contact/smooth_collider.hpp,
// vertex_contacts.hpp); with the smooth body
// contact the bodies' sweeps interleave (one sweep of each body in turn), the contacts are lagged before each, and a
// joint affine correction of the bodies coupled by their contacts replaces each body's own
// (joint_affine_correction.hpp). The paper's and the friction floor and the impulse contact between bodies stay
// projections after the step (sim::step). What is carried from step to step is State::carry's BDF2 history (x_{n−1},
// v_{n−1} and that step's h), so a copy of the State is a checkpoint. No allocation per step once sizes settle.
class VertexBlockDescent final : public Integrator {
 public:
  // Counts over every step this object took, for benchmarks and tests.
  struct Statistics : MoveCounts {  // MoveCounts: the local solves, searches and refusals
    long long steps = 0;
    long long bdf2_steps = 0;          // the others were backward Euler
    long long colours_at_once = 0;     // colours whose vertices moved at once (move_colour_at_once)
    long long colours_one_by_one = 0;  // of those, colours its safeguard refused: then visited a vertex at a time
    long long sweeps = 0;              // sweeps over one body each (a step of two bodies and 4 sweeps counts 8)
    long long corrections = 0;         // of those, the sweeps a body's own coarse or affine correction came before
  };

  // `coarse`: the affine correction before each sweep; `aggregates`: the cells per body of the coarse level
  // (sim/integrators/coarse_space.hpp), 0 for none, kAutoAggregates for auto_coarse_cells by each body's size.
  static constexpr int kAutoAggregates = -1;
  // `impact_phase`: around an impact on a smooth contact the steps shrink to ω h ≤ it (solver.impact_phase).
  // `control` (solver.iterations): SweepControl::Count takes `sweeps` sweeps per step. With Converge each step sweeps
  // until a sweep moves no vertex by more than kConvergedMove of its body's mean edge, at least kLeastConvergeSweeps
  // and at most kMostConvergeSweeps times.
  static constexpr double kConvergedMove = 3e-4;
  static constexpr int kLeastConvergeSweeps = 2;
  static constexpr int kMostConvergeSweeps = 32;
  // With Auto vbd holds its error to the tolerance integrators.md documents (the volume within 1 %) by itself. Its
  // sweeps go on as Converge's, until a sweep moves no vertex by more than kConvergedMove × min(1, h /
  // kConvergedMoveStep) of the mean edge (a step's error shrinks with h, and so must what its sweeps leave), and its
  // steps halve where the gas's volume's local error per unit time exceeds kVolumeErrorRate × V
  // (volume_error_ratio), as well as around impacts.
  static constexpr double kConvergedMoveStep = 1.0 / 30.0;  // [s]
  static constexpr double kVolumeErrorRate = 5e-3;          // [1/s]
  VertexBlockDescent(SweepControl control, int sweeps, bool coarse = true, int aggregates = 0,
                     double impact_phase = kVbdImpactPhase)
      : sweep_control_(control),
        sweeps_(sweeps),
        coarse_(coarse),
        aggregates_(aggregates),
        impact_phase_(impact_phase) {}
  // `sweeps` sweeps per step (SweepControl::Count).
  explicit VertexBlockDescent(int sweeps, bool coarse = true, int aggregates = 0)
      : VertexBlockDescent(SweepControl::Count, sweeps, coarse, aggregates) {}
  void set_up(const Model& model, PartRunner& runner) override;
  void step(Dynamics& dynamics, State& state, double dt) override;
  const Statistics& statistics() const { return statistics_; }

 private:
  // The bodies' layouts, at set_up or the first step (again for a model with other bodies).
  void prepare_once(const Model& model);
  // The keyframed smooth colliders at their pose at time t (the static ones stay as prepare_once made them).
  void pose_smooth_colliders(const Model& model, double time_s);
  // The level of the next step (its size is dt / 2^level) after `done` ticks of dt / 2^kDeepestLevel: deeper for
  // an impact on a smooth contact or, holding its own error, where the volume's is too large; one up where the two
  // steps before allow it (then BDF2 takes its history from two steps back, so every BDF2 step has a step ratio of at
  // most 1).
  struct StepLevel {
    int level = 0;
    bool impact = false;  // set by an impact on a smooth contact
  };
  StepLevel next_level(const Model& model, const State& state, double dt, int level, long long done) const;
  // Whether the last three states (steps of h) are smooth enough for a step of 2h (see kGrowthTolerance).
  bool smooth_enough_to_double(const Model& model, const State& state, double h) const;
  // The largest over the bodies with gas of BDF2's local error in V per unit time, estimated from the last three
  // states (steps of h), as a fraction of kVolumeErrorRate × V.
  double volume_error_ratio(const Model& model, const State& state) const;
  // The ω [1/s] of the stiffest smooth contact (floor, collider or body) that a step of h from state meets as an impact
  // (see kImpactAcceleration); 0 for none.
  double impact_omega(const Model& model, const State& state, double h) const;
  // One implicit step of h.
  void take_step(const Model& model, State& state, double h);
  // y, x̃ and ĥ of this step into target_, base_ (BDF2 with the step ratio ω = h_n/h_{n−1} from the history
  // x_previous, v_previous; backward Euler where ratio is 0), state's x and v into start_x_, start_v_, and y into
  // state.x as the first iterate; returns ĥ [s].
  double set_targets(const Model& model, State& state, double h, double ratio, const std::vector<Vec3>& x_previous,
                     const std::vector<Vec3>& v_previous);
  // What body b's local solves read (without the contacts between bodies).
  BodySolve body_solve(const Model& model, std::size_t b, double h_hat) const;
  // Sweeps first_sweep .. first_sweep + count − 1 of a step over body b's vertices (all solver.iterations of them,
  // from x = y, without contacts between bodies). `carried_volume`: the body's V at x where the caller knows it
  // exactly (the sweep before ended there). Returns V after the last sweep (0 without gas) [m³].
  double sweep_body(const Model& model, std::size_t b, double h_hat, std::vector<Vec3>& x, int first_sweep, int count,
                    std::optional<double> carried_volume = std::nullopt);
  // The sweeps of a step over body b alone (without contacts between bodies): solver.iterations of them, or with
  // SweepControl::Converge or Auto until one moves no vertex by more than the tolerance.
  void sweep_body_to_the_end(const Model& model, std::size_t b, double h_hat, std::vector<Vec3>& x);
  // solver.iterations sweeps (or with Converge or Auto, until one moves no vertex of any body by more than the
  // tolerance) over every body in turn, the smooth body contacts lagged before each.
  void sweep_in_contact(const Model& model, double h_hat, std::vector<Vec3>& x);
  // Whether the sweep that started at sweep_start_ (every vertex) moved no vertex of `bodies` by more than
  // kConvergedMove of its body's mean edge (with SweepControl::Auto, scaled by the step).
  bool sweep_was_still(std::span<const Body> bodies, const std::vector<Vec3>& x) const;
  // One sweep over body s's vertices, colour by colour: each colour at once on the threads (move_colour_at_once)
  // unless body contacts couple its vertices or the safeguard refuses, then one vertex at a time.
  void sweep_colours(const BodySolve& s, const ThreadShares& shares, const LaneGroups& groups, std::span<Vec3> x,
                     double& volume);
  // One vertex's Newton step with its line search; `volume`: the body's V, kept exact.
  void visit_vertex(const BodySolve& s, int i, std::span<Vec3> x, double& volume);

  // Whether the sweeps go on until still (Converge, Auto), and whether vbd holds its own error (Auto).
  bool sweeps_until_still() const { return sweep_control_ != SweepControl::Count; }
  bool holds_its_error() const { return sweep_control_ == SweepControl::Auto; }

  SweepControl sweep_control_ = SweepControl::Count;
  int sweeps_ = 1;            // per step, with SweepControl::Count
  double step_s_ = 0.0;       // the h of the step being taken [s]
  bool impact_step_ = false;  // whether its level was set by an impact (next_level)
  bool coarse_ = true;        // the affine coarse correction before each sweep
  AffineScratch coarse_scratch_;
  int aggregates_ = 0;                      // the coarse level's cells per body (0: none; kAutoAggregates)
  double impact_phase_ = kVbdImpactPhase;   // the impacts' steps keep ω h ≤ this
  std::vector<CoarseSpace> coarse_spaces_;  // per body; aggregates 0 where it has no coarse level
  CoarseScratch coarse_level_scratch_;
  std::size_t coarse_level_body_ = 0;             // the body whose matrix coarse_level_scratch_ holds
  long long coarse_matrix_age_ = 0;               // steps of this call of step() that began with the coarse level
  double coarse_matrix_h_ = 0.0;                  // the ĥ of the step its matrix was last assembled or reused at [s]
  std::size_t affine_body_ = 0;                   // the body whose affine matrix coarse_scratch_ holds
  std::vector<VertexBlocks> blocks_;              // per body
  std::vector<ThreadShares> shares_;              // per body, for the runner's threads
  std::vector<LaneGroups> lane_groups_;           // per body, for shares_ and the lanes' width
  std::optional<SmoothFloor> smooth_floor_;       // the floor's constants when its contact is smooth
  std::vector<SmoothCollider> smooth_colliders_;  // the colliders whose contact is smooth
  VertexContacts contacts_;                       // the smooth contact between bodies
  std::vector<BodySolve> joint_solves_;           // per body, for the joint affine correction
  JointAffineScratch joint_scratch_;
  bool joint_affine_ = false;  // this step's sweeps take the joint affine correction instead of each body's own
  std::vector<Vec3> target_;   // y per vertex [m]
  std::vector<Vec3> base_;     // x̃ per vertex [m]
  std::vector<Vec3> start_x_, start_v_;  // x_n, v_n (then the next step's history)
  ConstraintLags lags_;                  // scratch: one vertex's constraints as its visit found them
  ColourScratch colour_scratch_;         // scratch of the colours moved at once
  PartRunner* runner_ = nullptr;         // the workspace's threads, set by step()
  std::vector<double> volume_sums_;      // scratch: the volume's partial sums
  // A body's mass and the momentum it brings to the floor within a step, as impact_omega() sums them in chunks.
  struct FloorApproach {
    double mass_kg = 0.0;
    double approach_kg_m_per_s = 0.0;  // Σ m |v_y| of the vertices reaching the floor
    FloorApproach& operator+=(const FloorApproach& other) {
      mass_kg += other.mass_kg;
      approach_kg_m_per_s += other.approach_kg_m_per_s;
      return *this;
    }
  };
  mutable std::vector<FloorApproach> approach_sums_;  // scratch: impact_omega()'s partial sums
  std::vector<Vec3> sweep_start_;                     // scratch: x before a sweep, where the sweeps stop by themselves
  Statistics statistics_;
};

}  // namespace sim
