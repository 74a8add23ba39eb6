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
#include "sim/integrators.hpp"

namespace sim {

class World final : public Dynamics {
 public:
  World(const Vec3& gravity_m_per_s2, std::optional<scene::Floor> floor, scene::Integrator integrator);
  // With the scene's solver settings: the integrator, rk45's tolerance and first trial step.
  World(const Vec3& gravity_m_per_s2, std::optional<scene::Floor> floor, const scene::Solver& solver);

  // Appends a body whose vertices start at `x0` (world coordinates) with the common velocity `v0`.
  void add_body(Topology topology, const Params& params, const std::vector<Vec3>& x0, const Vec3& v0);

  // Restitution and friction of contacts between bodies (only searched for when there are several).
  void set_body_contact(const BodyContactSettings& settings) { body_contact_ = settings; }

  // One time step of dt seconds: integrate (forces evaluated inside) → body contacts → floor contact →
  // check.
  // Throws softbody::DivergedError when a position or velocity is no longer finite.
  // Fixed-step integrators run exactly this path; an adaptive one takes a step of exactly dt.
  void step(double dt);

  // True when the integrator chooses its own steps (rk45): drive it with advance_to().
  bool adaptive() const { return integrator_->adaptive() != nullptr; }

  // Adaptive integrators: steps of the size the error estimate proposes, each followed by floor contact
  // and the check like step(), the last one clipped so that time_s() lands exactly on `end_time_s`.
  // Rejected attempts leave the state untouched and are counted. Throws softbody::DivergedError when the
  // step size underflows (the motion became unstable or the tolerance is unreachable).
  void advance_to(double end_time_s);

  // Dynamics: gravity, springs, dampers and pressure of every body, divided by the vertex masses.
  void accelerations(const State& state, std::vector<Vec3>& a) override;

  // Net force on every vertex of `state` [N] (what accelerations() divides by the masses).
  void forces(const State& state, std::vector<Vec3>& force) override;
  std::span<const double> vertex_masses() const override { return mass_; }
  std::vector<SpringSet> spring_sets() const override;

  const State& state() const { return state_; }
  // Writable state: the integrator forgets what it cached about the old one (Verlet's acceleration,
  // rk45's first stage), so changing the state between steps is safe.
  State& state() {
    integrator_->restart();
    return state_;
  }
  double time_s() const { return time_s_; }
  long long step_count() const { return step_count_; }  // accepted steps
  long long rejected_step_count() const { return rejected_step_count_; }  // adaptive integrators only
  const std::vector<Body>& bodies() const { return bodies_; }
  const Vec3& gravity() const { return gravity_; }
  const std::optional<scene::Floor>& floor() const { return floor_; }

  // A body's slice of the state arrays.
  std::span<const Vec3> positions(const Body& body) const;
  std::span<const Vec3> velocities(const Body& body) const;

 private:
  void resolve_contacts();
  void check_finite() const;
  void after_step(double dt);

  Vec3 gravity_;
  std::optional<scene::Floor> floor_;
  std::unique_ptr<Integrator> integrator_;
  std::vector<Body> bodies_;
  std::vector<double> mass_;                  // per vertex, all bodies
  std::vector<double> inverse_mass_;          // per vertex, all bodies
  State state_;
  double time_s_ = 0.0;
  long long step_count_ = 0;
  long long rejected_step_count_ = 0;
  double adaptive_dt_s_ = 1e-4;               // the step advance_to() tries next
  std::vector<Vec3> force_scratch_;
  std::vector<std::vector<Vec3>> area_scratch_;  // per body, one entry per vertex (add_pressure)
  BodyContactSettings body_contact_;
  BodyCollider collider_;
};

// Builds the world a scene describes: loads and validates every body's mesh, places it, and builds its
// springs and masses. Notes on what was fixed (e.g. a flipped winding) are appended to `notes`.
World build_world(const scene::Scene& scene, std::vector<std::string>& notes);

}  // namespace sim
