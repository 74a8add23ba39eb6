// The simulated world: bodies, gravity, floor, the shared state, and the step as a list of phases.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "sim/body.hpp"
#include "sim/body_collision.hpp"
#include "sim/guard.hpp"
#include "sim/integrators.hpp"
#include "sim/part_runner.hpp"

namespace sim {

class World final : public Dynamics {
 public:
  World(const Vec3& gravity_m_per_s2, std::optional<sim::Floor> floor, sim::IntegratorKind integrator);
  // With the scene's solver settings: the integrator, rk45's tolerance and first trial step.
  World(const Vec3& gravity_m_per_s2, std::optional<sim::Floor> floor, const sim::Solver& solver);

  // Appends a body whose vertices start at `x0` (world coordinates) with the common velocity `v0`.
  void add_body(Topology topology, const Params& params, const std::vector<Vec3>& x0, const Vec3& v0);

  // Restitution and friction of contacts between bodies (only searched for when there are several).
  void set_body_contact(const ContactMaterial& material) { body_contact_ = material; }

  // One time step of dt seconds: integrate (forces evaluated inside) → body contacts → floor contact →
  // guard (sim/guard.hpp). When the guard finds a divergence and solver.retry is on, the step is redone
  // from its start as 2, 4, .. 1024 substeps, and later steps keep the substep count that worked (a dt
  // above the stable limit stays unstable). Otherwise, or if 1024 fail too, it throws
  // softbody::DivergedError saying when, where, what, and which dt the estimate (sim/stability.hpp) finds stable.
  // Fixed-step integrators run exactly this path; an adaptive one takes a step of exactly dt.
  void step(double dt);

  // The guard's full check of the current state (energy and volume too), which step() runs only every
  // kFullCheckInterval steps: the frame loops call it before handing a frame out, so that no frame of a
  // diverged state is written. Throws softbody::DivergedError like step().
  void check_state();
  static constexpr int kFullCheckInterval = 8;  // steps between the guard's energy and volume checks

  // Bodies of at least kParallelMinVertices vertices run their force passes on two threads when
  // solver.threads allows: the edges (springs, dampers) on one while the faces (the gas's area sums and
  // volume) run on the other, then the last per-vertex pass in two vertex ranges. Each sum is the one the
  // single-threaded pass computes, in the same order, so the result is the same bit for bit. Smaller
  // bodies do not pay for the hand-over.
  static constexpr int kParallelMinVertices = 4096;
  static constexpr int kMostForceThreads = 2;
  int force_threads() const { return threads_; }

  // The step advance_to() tries first (solver.dt, or the "auto" estimate).
  void set_trial_dt(double dt) { adaptive_dt_s_ = dt; }
  long long retried_step_count() const { return retried_step_count_; }  // solver.retry: steps redone
  int substeps() const { return substeps_; }  // solver.retry: each step is now this many substeps

  // True when the integrator chooses its own steps (rk45): drive it with advance_to().
  bool adaptive() const { return integrator_->adaptive() != nullptr; }

  // Adaptive integrators: steps of the size the error estimate proposes, each followed by floor contact
  // and the check like step(), the last one clipped so that time_s() lands exactly on `end_time_s`.
  // Rejected attempts (error above the tolerance, or a step the guard rejects) leave the state untouched,
  // are counted, and shrink the step. Throws softbody::DivergedError when the step size underflows (the
  // motion became unstable or the tolerance is unreachable), with the guard's last finding.
  void advance_to(double end_time_s);

  // Dynamics: gravity, springs, dampers and pressure of every body, divided by the vertex masses.
  void accelerations(const State& state, std::vector<Vec3>& a) override;

  // Net force on every vertex of `state` [N] (what accelerations() divides by the masses).
  void forces(const State& state, std::vector<Vec3>& force) override;
  // Forward or symplectic Euler with the update applied in the last per-vertex force pass.
  void first_order_step(State& state, double dt, FirstOrderUpdate update, std::vector<Vec3>& scratch) override;
  std::span<const double> vertex_masses() const override { return mass_; }
  std::vector<SpringSet> spring_sets() const override;

  const State& state() const { return state_; }
  // Writable state: the integrator forgets what it cached about the old one (Verlet's acceleration,
  // rk45's first stage), so changing the state between steps is safe.
  State& state() {
    integrator_->restart();
    reversed_.clear();  // the integrator was told to forget them
    guard_.rebase();
    return state_;
  }
  double time_s() const { return time_s_; }
  long long step_count() const { return step_count_; }  // accepted steps
  long long rejected_step_count() const { return rejected_step_count_; }  // adaptive integrators only
  const std::vector<Body>& bodies() const { return bodies_; }
  const Vec3& gravity() const { return gravity_; }
  const std::optional<sim::Floor>& floor() const { return floor_; }

  // A body's slice of the state arrays.
  std::span<const Vec3> positions(const Body& body) const;
  std::span<const Vec3> velocities(const Body& body) const;

 private:
  // A body's gravity, springs and dampers, summed into f (overwritten).
  void spring_forces(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v, std::span<Vec3> f) const;
  // Body b's gas: its area sums into area_scratch_[b]; returns the gas force per area sum (nRT / V / 6),
  // 0 without gas.
  double gas_face_pass(std::size_t b, std::span<const Vec3> x);
  // Evaluates every body's forces (partial sums in `scratch`) and then, in one pass per body, hands each
  // vertex's net force to use(i, f_i), i the world vertex index. `use` may overwrite scratch[i] and the
  // body's own x_i, v_i: the body's forces are complete before its pass.
  template <class Use>
  void visit_net_forces(const State& state, std::vector<Vec3>& scratch, Use use);
  // visit_net_forces for one body on two threads (see kParallelMinVertices).
  template <class Use>
  void visit_body_forces_in_parallel(std::size_t b, const State& state, std::span<Vec3> f, Use& use);
  template <FirstOrderUpdate kUpdate>
  void fused_first_order_step(State& state, double dt, std::vector<Vec3>& scratch);
  void resolve_contacts();
  // Integrate, resolve contacts, and ask the guard: the problem found, if any.
  std::optional<Divergence> integrate_and_check(double dt);
  // dt as substeps_ substeps, each checked: the first problem found.
  std::optional<Divergence> substep(double dt);
  // After a failed step from backup_: twice the substeps until one works; false past 1024.
  bool retry_with_substeps(double dt);
  [[noreturn]] void throw_diverged(const Divergence& found, double dt) const;

  Vec3 gravity_;
  std::optional<sim::Floor> floor_;
  std::unique_ptr<Integrator> integrator_;
  std::vector<Body> bodies_;
  std::vector<double> mass_;                  // per vertex, all bodies
  std::vector<double> inverse_mass_;          // per vertex, all bodies
  State state_;
  double time_s_ = 0.0;
  long long step_count_ = 0;
  long long rejected_step_count_ = 0;
  double adaptive_dt_s_ = 1e-4;               // the step advance_to() tries next
  std::vector<std::vector<Vec3>> area_scratch_;  // per body, one entry per vertex (add_pressure)
  std::vector<int> reversed_;                     // vertices the paper's floor response reversed this step
  std::vector<int> backup_reversed_;              // reversed_ when backup_ was taken (retry)
  ContactMaterial body_contact_;
  BodyCollider collider_;
  DivergenceGuard guard_;
  int steps_since_full_check_ = 0;
  double last_dt_s_ = 0.0;  // the last fixed step taken, for messages
  sim::IntegratorKind integrator_kind_;
  bool retry_ = false;
  int threads_ = 1;  // for large bodies' force passes, 1 .. kMostForceThreads
  std::unique_ptr<PartRunner> part_runner_;   // runs those parts (its workers start when first needed)
  long long retried_step_count_ = 0;
  int substeps_ = 1;
  State backup_;                              // the state before the step (retry, rk45)
  std::vector<Vec3> initial_x_;               // positions as built, for the stable-dt advice
};

// Builds the world a scene describes: loads and validates every body's mesh, places it, and builds its
// springs and masses. Notes on what was fixed (e.g. a flipped winding) are appended to `notes`.
World build_world(const scene::Scene& scene, std::vector<std::string>& notes);

}  // namespace sim
