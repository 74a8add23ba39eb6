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

  // Appends a body whose vertices start at `x0` (world coordinates) with the common velocity `v0`.
  void add_body(Topology topology, const Params& params, const std::vector<Vec3>& x0, const Vec3& v0);

  // Restitution and friction of contacts between bodies (only searched for when there are several).
  void set_body_contact(const BodyContactSettings& settings) { body_contact_ = settings; }

  // One time step of dt seconds: integrate (forces evaluated inside) → body contacts → floor contact →
  // check.
  // Throws softbody::DivergedError when a position or velocity is no longer finite.
  void step(double dt);

  // Dynamics: gravity, springs, dampers and pressure of every body, divided by the vertex masses.
  void accelerations(const State& state, std::vector<Vec3>& a) override;

  // Net force on every vertex of `state` [N] (what accelerations() divides by the masses).
  void forces(const State& state, std::vector<Vec3>& force);

  const State& state() const { return state_; }
  State& state() { return state_; }
  double time_s() const { return time_s_; }
  long long step_count() const { return step_count_; }
  const std::vector<Body>& bodies() const { return bodies_; }
  const Vec3& gravity() const { return gravity_; }
  const std::optional<scene::Floor>& floor() const { return floor_; }

  // A body's slice of the state arrays.
  std::span<const Vec3> positions(const Body& body) const;
  std::span<const Vec3> velocities(const Body& body) const;

 private:
  void resolve_contacts();
  void check_finite() const;

  Vec3 gravity_;
  std::optional<scene::Floor> floor_;
  std::unique_ptr<Integrator> integrator_;
  std::vector<Body> bodies_;
  std::vector<double> inverse_mass_;          // per vertex, all bodies
  State state_;
  double time_s_ = 0.0;
  long long step_count_ = 0;
  std::vector<Vec3> force_scratch_;
  std::vector<std::vector<Vec3>> area_scratch_;  // per body, one entry per face
  BodyContactSettings body_contact_;
  BodyCollider collider_;
};

// Builds the world a scene describes: loads and validates every body's mesh, places it, and builds its
// springs and masses. Notes on what was fixed (e.g. a flipped winding) are appended to `notes`.
World build_world(const scene::Scene& scene, std::vector<std::string>& notes);

}  // namespace sim
