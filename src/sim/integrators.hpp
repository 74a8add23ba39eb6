// Time integrators. Each sees the system only through Dynamics ("accelerations of this state", plus the
// spring network for the implicit method), so forces, contacts and guards are written once for all of them.
//
// Every integrator advances the smooth equations of motion ẋ = v, v̇ = a(x, v). Floor contact is not part
// of them: World::step projects the state after each step. A step that contains a contact event is
// therefore only first order (the event is resolved at step granularity) whatever the integrator; steps
// without contact keep the integrator's own order.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "scene/scene.hpp"
#include "sim/body.hpp"

namespace sim {

// One body's spring-dampers in world vertex numbering, for integrators that linearise the forces.
struct SpringSet {
  std::span<const std::array<int, 2>> edges;  // local vertex indices; add first_vertex for the state's
  std::span<const double> rest_length_m;
  double stiffness_N_per_m = 0.0;
  double damping_N_s_per_m = 0.0;
  int first_vertex = 0;
};

// The two first-order explicit updates, both from a = a(x, v) of the state at the start of the step.
enum class FirstOrderUpdate {
  Forward,     // x' = x + h v, v' = v + h a        (forward Euler)
  Symplectic,  // v' = v + h a, x' = x + h v'       (semi-implicit Euler)
};

class Dynamics {
 public:
  virtual ~Dynamics() = default;
  // a_i = f_i(x, v) / m_i for every vertex of `state` [m/s²]; `a` is resized by the callee.
  virtual void accelerations(const State& state, std::vector<Vec3>& a) = 0;
  // f_i(x, v) for every vertex [N]; `force` is resized by the callee.
  virtual void forces(const State& state, std::vector<Vec3>& force) = 0;
  // m_i of every vertex [kg].
  virtual std::span<const double> vertex_masses() const = 0;
  // The spring-dampers of every body (the stiff, linearisable part of the forces).
  virtual std::vector<SpringSet> spring_sets() const = 0;
  // One first-order step of `state` by dt. This default evaluates accelerations() into `scratch` and then
  // updates every vertex; World overrides it to apply the update in its last per-vertex force pass
  // (same arithmetic, same result bit for bit, one pass over the vertices fewer).
  virtual void first_order_step(State& state, double dt, FirstOrderUpdate update, std::vector<Vec3>& scratch);
};

// x, v of one vertex after one first-order update with acceleration a.
inline void apply_first_order_update(FirstOrderUpdate update, double dt, const Vec3& a, Vec3& x, Vec3& v) {
  if (update == FirstOrderUpdate::Forward) {
    x += dt * v;  // the old velocity: explicit in both
    v += dt * a;
  } else {
    v += dt * a;
    x += dt * v;  // the new velocity
  }
}

class AdaptiveIntegrator;

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Advances `state` by dt seconds (adaptive methods: one step of exactly dt, without error control).
  virtual void step(Dynamics& dynamics, State& state, double dt) = 0;
  // The state was changed from outside (a contact projection, a user): forget what was cached about it.
  virtual void restart() {}
  // The floor reversed the whole velocity of these vertices (the paper's response, v ← −v, after restart()).
  // For an integrator whose velocity lives at the same time as the positions this is the time reversal of
  // the vertex's motion and needs nothing; symplectic Euler, whose velocity is half a step off, overrides it.
  virtual void velocities_reversed(std::span<const int> /*vertices*/) {}
  // Non-null for integrators that choose their own step size.
  virtual AdaptiveIntegrator* adaptive() { return nullptr; }
};

// An integrator with error control: it tries a step, accepts or rejects it, and proposes the next size.
class AdaptiveIntegrator : public Integrator {
 public:
  struct Attempt {
    bool accepted = false;  // true: `state` advanced by dt; false: `state` untouched
    double next_dt_s = 0.0; // the step size the error estimate suggests next
  };
  virtual Attempt attempt(Dynamics& dynamics, State& state, double dt) = 0;
  AdaptiveIntegrator* adaptive() override { return this; }
};

// The integrator a scene names; `tolerance` is used by rk45 only.
std::unique_ptr<Integrator> make_integrator(sim::IntegratorKind kind, double tolerance);

}  // namespace sim
