// The equations of motion the integrators see: the net force on every vertex from the model's forces
// (gravity, springs, dampers, gas, the smooth floor and body contacts), a(x, v) = f / m, and the fused
// first-order step.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "sim/contact/body_collision.hpp"
#include "sim/contact/smooth_contact.hpp"
#include "sim/model/model.hpp"
#include "sim/model/state.hpp"
#include "sim/step/part_runner.hpp"

namespace sim {

// Bodies of at least kParallelMinVertices vertices run their force passes on two threads when
// solver.threads allows: the edges (springs, dampers) on one while the faces (the gas's area sums and
// volume) run on the other, then the last per-vertex pass in two vertex ranges. Each sum is the one the
// single-threaded pass computes, in the same order, so the result is the same bit for bit. Smaller bodies
// do not pay for the hand-over.
inline constexpr int kParallelMinVertices = 4096;
inline constexpr int kMostForceThreads = 2;

// The two first-order explicit updates, both from a = a(x, v) of the state at the start of the step.
enum class FirstOrderUpdate {
  Forward,     // x' = x + h v, v' = v + h a        (forward Euler)
  Symplectic,  // v' = v + h a, x' = x + h v'       (semi-implicit Euler)
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

// Scratch of the force evaluation, sized on first use; owned by the Workspace.
struct ForceScratch {
  explicit ForceScratch(int thread_count) : threads(thread_count), runner(std::make_unique<PartRunner>(thread_count)) {}
  int threads = 1;                           // for large bodies' force passes, 1 .. kMostForceThreads
  std::unique_ptr<PartRunner> runner;        // runs those parts (its workers start when first needed)
  std::vector<std::vector<Vec3>> area_sums;  // per body of the model, one entry per vertex: the gas's face pass
  std::vector<Vec3> net_force;               // every vertex: the fused step's partial sums
  BodyCollider collider;                     // the smooth body contact's search
  std::vector<Vec3> contact_force;           // every vertex: the smooth body contact's forces
};

class Dynamics {
 public:
  Dynamics(const Model& model, ForceScratch& scratch);

  const Model& model() const { return model_; }
  // The workspace's threads (solver.threads, at most kMostForceThreads), for integrators that split their own loops.
  PartRunner& runner() const { return *scratch_.runner; }

  // f_i(x, v) for every vertex of `state` [N]; `force` is resized here.
  void forces(const State& state, std::vector<Vec3>& force);
  // a_i = f_i(x, v) / m_i for every vertex [m/s²]; `a` is resized here.
  void accelerations(const State& state, std::vector<Vec3>& a);
  // f_i of gravity and the gas only, without springs, dampers and bending links [N] (xpbd's prediction: those
  // are its constraints); `force` is resized here. One thread.
  void gravity_and_gas_forces(const State& state, std::vector<Vec3>& force);
  // One forward or symplectic Euler step of `state` by dt, the update applied in the force evaluation's
  // last per-vertex pass (the same arithmetic as accelerations() and then the update: one pass fewer).
  void first_order_step(State& state, double dt, FirstOrderUpdate update);

 private:
  // Evaluates every body's forces (partial sums in `partial`) and then, in one pass per body, hands each
  // vertex's net force to use(i, f_i), i the state's vertex index. `use` may overwrite partial[i] and the
  // body's own x_i, v_i: the body's forces are complete before its pass.
  template <class Use>
  void visit_net_forces(const State& state, std::vector<Vec3>& partial, Use use);
  // visit_net_forces for one body on two threads (see kParallelMinVertices).
  template <class Use>
  void visit_body_forces_in_parallel(std::size_t b, const State& state, std::span<Vec3> f, bool body_contact, Use& use);
  template <FirstOrderUpdate kUpdate>
  void fused_first_order_step(State& state, double dt);
  // Gravity, then the springs and dampers (one fused pass) and the bending links' (another), summed into f
  // (overwritten).
  void gravity_and_spring_forces(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v,
                                 std::span<Vec3> f) const;
  // The smooth floor contact's forces added to f (only with floor.contact smooth; the other contacts are
  // projections after the step, sim/step/step.cpp).
  void floor_contact_forces(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v,
                            std::span<Vec3> f) const;
  // The smooth colliders' contact forces added to f (only for colliders whose contact is smooth; the others are
  // projections after the step), each collider at its pose at time_s (the state's: a step's start). Nothing
  // without colliders.
  void collider_contact_forces(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v, double time_s,
                               std::span<Vec3> f) const;
  // Body b's gas: its area sums into scratch_.area_sums[b]; returns the gas force per area sum (nRT / V / 6),
  // 0 without gas.
  double gas_face_pass(std::size_t b, std::span<const Vec3> x);

  const Model& model_;
  ForceScratch& scratch_;
  // The smooth body contact's forces of the whole state into scratch_.contact_force (they couple the bodies,
  // so all are found before any body's net force is handed out). False when there are none to add.
  bool body_contact_forces(const State& state);

  std::optional<SmoothFloor> smooth_floor_;      // the floor's constants when its contact is a force
  std::optional<SmoothResponse> smooth_bodies_;  // the bodies' contact constants when theirs is a force
};

}  // namespace sim
